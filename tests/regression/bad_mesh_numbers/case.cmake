# Bad input stops with exit code 2 before any solving, with a message naming the problem.
# A Mesh Numbers entry the .geo does not define with DefineConstant.
cgcm_bad_input(SANITIZE REGEX "override \"nn\".*sphere-on-half-space.geo.*DefineConstant")
