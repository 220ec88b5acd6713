# Bad input stops with exit code 2 before any solving, with a message naming the problem.
# Method 1 takes linear cells only (its pair list bounds a cell by its nodes, which a curved
# cell may leave): Geometry/Element Order = 2 is refused before the mesh is made.
cgcm_bad_input(SANITIZE REGEX "Interaction/Method = .volume pair. takes linear cells .*Geometry/Element Order = 2")
