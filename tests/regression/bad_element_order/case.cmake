# Bad input stops with exit code 2 before any solving, with a message naming the problem.
# Geometry/Element Order takes 1 (linear cells) or 2 (quadratic): 3 is refused with the
# parameter and the allowed values.
cgcm_bad_input(SANITIZE REGEX "Geometry/Element Order = 3: out of range; allowed: 1 \\.\\. 2")
