# Bad input stops with exit code 2 before any solving, with a message naming the problem.
# A drive vector that does not fit the mesh (inputs/3d/two-spheres.xml). Here: it moves
# the symmetry plane x = 0.
cgcm_bad_input(SANITIZE REGEX "its x component moves .*symmetry x")
