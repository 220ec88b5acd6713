# Bad input stops with exit code 2 before any solving, with a message naming the problem.
# Numbers that are not numbers stop before any work, with the parameter's path. Here: a
# double that is not a number (Teuchos alone would read 0).
cgcm_bad_input(SANITIZE REGEX "Material/Poisson's Ratio: \"abc\" is not a number")
