# Bad input stops with exit code 2 before any solving, with a message naming the problem.
# Preconditioner Reuse with a direct solver (the default deck is axisymmetric: auto is MUMPS) would be
# ignored without a word: it is refused, naming the solver the run has.
cgcm_bad_input(SANITIZE DECK ../../../inputs/sphere-on-half-space.xml ARGS "Solver/Linear Solver/Preconditioner Reuse=2"
               REGEX "Solver/Linear Solver/Preconditioner Reuse = 2 applies to the Belos types, and this run's linear solver is MUMPS")
