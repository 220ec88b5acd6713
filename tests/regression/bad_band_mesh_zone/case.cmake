# Bad input stops with exit code 2 before any solving, with a message naming the problem.
# A band wider than the sphere (gmsh itself would crash on the arc).
cgcm_bad_input(SANITIZE REGEX "band.geo: need .*0 < zone < 1")
