# Bad input stops with exit code 2 before any solving, with a message naming the problem.
# Method 3 projects onto curved segments in 2D, but not onto the curved facets of quadratic 3D
# cells: the 3D hexahedral deck with Geometry/Element Order = 2 is refused before the mesh is made.
cgcm_bad_input(SANITIZE REGEX "Interaction/Method = .half-space point. takes linear cells in 3D .*Geometry/Element Order = 2")
