# Bad input stops with exit code 2 before any solving, with a message naming the problem.
# Inf in the approach path given on the command line (deck.xml is a link to the default
# deck).
cgcm_bad_input(SANITIZE ARGS "Loading/Approach Path={-0.02,inf}"
               REGEX "Loading/Approach Path: \"inf\" is not a finite number")
