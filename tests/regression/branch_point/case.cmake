# A branch point in adhesion (doc/validation.md, "Branch points"): a cylindrical
# tip lowered into the groove between two ridges, the whole model exactly
# symmetric, under arc-length control with the tangent's eigenvalues
# (Output/Eigenvalues = 3) and Branch Switching. The symmetric path has two
# branch points, where the count of negative eigenvalues changes by one without
# a fold: at u = 0.0364877 the tip loses stability to a sideways mode (before
# the jump-in fold at 0.0365129) and regains it at u = 0.0286514 on the contact
# branch. Between them the parity of folds calls rows stable that are not
# (stable_by_folds = 1, stable = 0); nowhere else do the two differ. Each of the
# two branches switched to is the asymmetric one (the tip on one flank), stable
# for u in [0.0275, 0.0372], and ends where it rejoins the path at the other
# branch point (a fold of the branch within 1e-6 of it in u). Tolerance 1e-6 in u:
# the branch points are located to solver tolerance (1e-11 of the step in arc
# length, about 1e-9 in u); 1e-6 is far below the steps (1e-3) and allows for
# round-off on other machines and rank counts.
cgcm_run()
cgcm_check(COMMAND ${check} branches ${run}/load_curve.csv --at 0.0364877 0.0286514 --abs 1e-6 --stable-branch)
# Every row written is converged (residual below 1e-10) and summary.txt says "completed".
cgcm_check(AS converged COMMAND ${check} converged ${run}/load_curve.csv --tolerance 1e-10 --summary ${run}/summary.txt)
# A switch that fails (Switch Amplitude 0.5, ten times the gap: no converged point there) does not stop the
# run: the path completes (exit 0) and summary.txt, printed at the end, says which switch failed and why.
cgcm_app_check(AS failed_switch ARGS ${case_dir}/deck.xml Output/Directory=${run}_failed_switch Output/Exodus=false
               "Loading/Switch Amplitude=0.5" EXIT 0
               STDOUT "note: branch switching at u = 0.0364.*the other branch is not followed")
