# Bad input stops with exit code 2 before any solving, with a message naming the problem.
# A drive vector that does not fit the mesh (inputs/3d/two-spheres.xml). Here: given with
# Drive Direction.
cgcm_bad_input(SANITIZE REGEX "Drive Vector: give it, or Drive Direction")
