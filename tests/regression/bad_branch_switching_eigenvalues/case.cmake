# Bad input stops with exit code 2 before any solving, with a message naming the problem.
# Branch Switching finds branch points from the tangent's eigenvalues: it needs Output/Eigenvalues > 0.
cgcm_bad_input(SANITIZE DECK ../branch_point/deck.xml ARGS Output/Eigenvalues=0
               REGEX "Loading/Branch Switching = true: .*Output/Eigenvalues > 0")
