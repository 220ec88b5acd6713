# Folds: gammaW = 20 (Tabor 1.19) jumps into contact on approach and off it on
# retraction (level 0). Displacement control (../jumps): exactly two folds,
# each followed by a jump landing in and out of contact (r_S0 = 0.0127).
# Arc-length control (../arc_length_loop): the whole loop, four folds with
# unstable rows exactly between them. Where both are stable they are the same
# equilibria (../arc_length): at the waypoints u = 0.01 (contact branch) and
# u = -0.04 (after pull-off) P agrees to twice the residual tolerance (1e-10
# F_ref each), and the folds that end stable branches are where displacement
# control jumps (to 1e-8 in u: both located to solver tolerance, from
# different starting points).
cgcm_run()
cgcm_check(COMMAND ${check} folds ${run}/load_curve.csv --expected 4 --unstable)
# Every row written is converged (residual below 1e-10) and summary.txt says "completed".
cgcm_check(AS converged COMMAND ${check} converged ${run}/load_curve.csv --tolerance 1e-10 --summary ${run}/summary.txt)
# The same loop with the tangent's eigenvalues (Output/Eigenvalues = 2): stability from the eigenvalues agrees
# with the parity of the folds on every row but the folds (marginal), there is no branch point, and the
# unstable branches are there (23 rows).
cgcm_run(AS eigenvalues ARGS Output/Eigenvalues=2)
cgcm_check(AS eigenvalues_agree_with_folds FIXTURES ${name}_eigenvalues
           COMMAND ${check} criteria ${run}_eigenvalues/load_curve.csv --min-unstable 20)
