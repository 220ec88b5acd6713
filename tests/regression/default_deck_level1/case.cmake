# The default deck at mesh level 1 (a state that used to be accepted at a
# Newton cycle, u = 0.054 on retraction) runs to completion with every state
# below the tolerance (1e-10).
cgcm_run()
cgcm_check(COMMAND ${check} converged ${run}/load_curve.csv --tolerance 1e-10 --summary ${run}/summary.txt)
