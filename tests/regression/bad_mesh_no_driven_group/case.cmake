# Bad input stops with exit code 2 before any solving, with a message naming the problem.
# A valid mesh without the "driven" group the app needs (no-driven.geo).
cgcm_bad_input(SANITIZE REGEX "no-driven.geo.*no physical group \"driven\"")
