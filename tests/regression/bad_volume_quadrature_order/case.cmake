# Bad input stops with exit code 2 before any solving, with a message naming the problem.
# Max Volume Quadrature Order below Volume Quadrature Order (Method 1).
cgcm_bad_input(SANITIZE REGEX "Max Volume Quadrature Order = 2 is below")
