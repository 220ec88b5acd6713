# Bad input stops with exit code 2 before any solving, with a message naming the problem.
# Absurd sizes are refused before the mesh is allocated, with the estimate: beyond the
# memory limit (the machine's, or Output/Max Memory), beyond the index range. Here: Mesh
# Refinement 6, beyond the machine's memory.
cgcm_bad_input(SANITIZE
               REGEX "Geometry/Mesh Refinement: the mesh would have 5.48e.06 nodes.* need about .* GB of memory, more than")
