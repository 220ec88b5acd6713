# Bad input stops with exit code 2 before any solving, with a message naming the problem.
# Bad 3D / many-body input stops before solving: a body the mesh does not have, a bad
# per-body material, bodies drawn into each other, a body free to move rigidly. Here: a
# bad per-body material.
# The body's override is checked as the Material sublist is: the same message, with its path.
cgcm_bad_input(SANITIZE REGEX "Bodies/substrate/Poisson's Ratio = 0.7: out of range. allowed: -0.999999 .. 0.499999")
