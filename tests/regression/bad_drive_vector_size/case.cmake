# Bad input stops with exit code 2 before any solving, with a message naming the problem.
# A drive vector that does not fit the mesh (inputs/3d/two-spheres.xml). Here: two entries
# on a 3D mesh.
cgcm_bad_input(SANITIZE REGEX "Drive Vector: 2 entries. the mesh is 3D")
