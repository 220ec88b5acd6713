# Bad input stops with exit code 2 before any solving, with a message naming the problem.
# A .geo that is not gmsh's language (malformed.geo).
cgcm_bad_input(SANITIZE REGEX "malformed.geo.*line 3")
