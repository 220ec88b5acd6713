# Continuation in gammaW at a fixed approach: from the default deck's contact
# state at u = 0.01 the adhesion grows (gammaW 200 -> 20) at fixed u; the end
# state is the gammaW = 20 contact state at u = 0.01 of ../jumps (P to 2e-10,
# twice the residual tolerance).
cgcm_run()
cgcm_check(FIXTURES ${name} regression_jumps
           COMMAND ${check} agree ${run}/load_curve.csv ${out}/regression_jumps/load_curve.csv --at 0.01 --tolerance 0
                   --abs 2e-10)
