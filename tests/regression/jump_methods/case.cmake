# The two jump methods land on the same far stable branches: relaxation (the
# default, ../jumps) and continuation along the unstable branch
# (../jumps_by_continuation) give the same folds and, after each jump, the
# same states (at the turning point u = 0.01 and at the end, to the solver
# tolerance: 2e-10 in P, twice the residual tolerance; 1e-8 in u for the folds).
# This case runs nothing: it compares the runs of ../jumps_by_continuation and ../jumps.
cgcm_check(AS agree FIXTURES regression_jumps regression_jumps_by_continuation
           COMMAND ${check} agree ${out}/regression_jumps_by_continuation/load_curve.csv
                   ${out}/regression_jumps/load_curve.csv --at 0.01 -0.04 --tolerance 0 --abs 2e-10)
cgcm_check(AS same_folds FIXTURES regression_jumps regression_jumps_by_continuation
           COMMAND ${check} foldsmatch ${out}/regression_jumps_by_continuation/load_curve.csv
                   ${out}/regression_jumps/load_curve.csv --tolerance 1e-8)
