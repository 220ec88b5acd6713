# Bad input stops with exit code 2 before any solving, with a message naming the problem.
# Out of range, in one line with the allowed values.
cgcm_bad_input(SANITIZE REGEX "Material/Poisson's Ratio = 0.7: out of range. allowed: -0.999999 .. 0.499999")
