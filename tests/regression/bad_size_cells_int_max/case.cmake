# Bad input stops with exit code 2 before any solving, with a message naming the problem.
# Absurd sizes are refused before the mesh is allocated, with the estimate: beyond the
# memory limit (the machine's, or Output/Max Memory), beyond the index range. Here: a
# block of 2^31 - 1 cells along x (inputs/examples/block-compression.xml).
cgcm_bad_input(SANITIZE
               REGEX "Geometry/Block/Cells X, Y, Z: the mesh would have .* beyond the 2.31 - 1 this code can index")
