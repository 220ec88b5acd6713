# Bad input stops with exit code 2 before any solving, with a message naming the problem.
# CG needs a symmetric tangent; Method 3's is not.
cgcm_bad_input(SANITIZE REGEX "Solver/Linear Solver/Type = \"Belos CG \\+ MueLu\" needs a symmetric tangent")
