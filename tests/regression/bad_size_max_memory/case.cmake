# Bad input stops with exit code 2 before any solving, with a message naming the problem.
# Absurd sizes are refused before the mesh is allocated, with the estimate: beyond the
# memory limit (the machine's, or Output/Max Memory), beyond the index range. Here: Mesh
# Refinement 2, beyond Output/Max Memory = 100 MB.
cgcm_bad_input(SANITIZE
               REGEX "Geometry/Mesh Refinement: .* need about 269 MB of memory, more than Output/Max Memory = 100 MB")
