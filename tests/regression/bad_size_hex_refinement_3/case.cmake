# Bad input stops with exit code 2 before any solving, with a message naming the problem.
# Absurd sizes are refused before the mesh is allocated, with the estimate: the built-in 3D
# quarter model (inputs/3d/sphere-on-half-space-hex.xml) at Mesh Refinement 3 has 64 cells
# over the quarter and 4.85e6 nodes (mesh::sphereOnHalfSpaceQuarterSize), beyond the machine's memory.
cgcm_bad_input(SANITIZE
               REGEX "Geometry/Mesh Refinement: the mesh would have 4.85e.06 nodes.* need about .* GB of memory, more than")
