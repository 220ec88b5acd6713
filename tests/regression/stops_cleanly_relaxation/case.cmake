# A step that does not converge is never written: with one Newton iteration
# allowed (the rigid approach from beyond the cutoff needs no more) the steps
# fail at the jump-to-contact and so does the jump, by continuation (LOCA,
# capped at 30 steps) or by relaxation (capped at 3 iterations); the run stops
# with exit code 1, the summary says why, and every row written is converged.
# Here: the jump by relaxation.
cgcm_run(EXIT 1 STDERR "cgcm: stopped after step [0-9]+: ")
cgcm_check(COMMAND ${check} converged ${run}/load_curve.csv --tolerance 1e-10 --summary ${run}/summary.txt --stopped)
