# Bad input stops with exit code 2 before any solving, with a message naming the problem.
# Branch points are located on arc-length paths: Branch Switching refuses displacement control.
cgcm_bad_input(SANITIZE DECK ../branch_point/deck.xml ARGS Loading/Control=displacement
               REGEX "Loading/Branch Switching = true: .*arc-length")
