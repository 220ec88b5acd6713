# Bad input stops with exit code 2 before any solving, with a message naming the problem.
# An unknown parameter, with the nearest valid name and the allowed ones.
cgcm_bad_input(SANITIZE
               REGEX "Interaction/gamaW: unknown parameter .did you mean \"gammaW\"... allowed in Interaction: \"Potential\"")
