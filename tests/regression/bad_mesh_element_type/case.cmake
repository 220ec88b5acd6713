# Bad input stops with exit code 2 before any solving, with a message naming the problem.
# Triangles, which the FE core does not support in 2D (triangles.geo).
cgcm_bad_input(SANITIZE REGEX "triangles.geo.*\"Triangle 3\"")
