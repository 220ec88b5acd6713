# The two jump methods land on the same far stable branches: relaxation (the
# default, ../jumps) and continuation along the unstable branch
# (../jumps_by_continuation) give the same folds and, after each jump, the
# same states (at the turning point u = 0.01 and at the end, to the solver
# tolerance: 2e-10 in P, twice the residual tolerance; 1e-8 in u for the folds).
# Here: the loop of ../jumps with Loading/Jump Method = continuation, two folds
# and two jumps as there (../jump_methods compares the two).
cgcm_run()
cgcm_check(COMMAND ${check} jumps ${run}/load_curve.csv --expected 2 --contact-gap 0.02)
