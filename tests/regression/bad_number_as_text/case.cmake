# Bad input stops with exit code 2 before any solving, with a message naming the problem.
# Numbers that are not numbers stop before any work, with the parameter's path. Here: a
# number given as text.
cgcm_bad_input(SANITIZE REGEX "Material/Young's Modulus: \"one\" is not a number")
