# Continuation in gammaL (the length scale r0 = R0 / gammaL at fixed gammaW)
# there and back, 50 -> 40 -> 50 at u = 0.01: the load changes on the way and
# returns to the start state (twice the residual tolerance).
cgcm_run()
cgcm_check(COMMAND ${check} returns ${run}/load_curve.csv --u 0.01 --abs 2e-10)
