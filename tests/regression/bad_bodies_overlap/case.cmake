# Bad input stops with exit code 2 before any solving, with a message naming the problem.
# Bad 3D / many-body input stops before solving: a body the mesh does not have, a bad
# per-body material, bodies drawn into each other, a body free to move rigidly. Here:
# bodies drawn into each other.
cgcm_bad_input(SANITIZE REGEX "bodies overlap in the reference configuration")
