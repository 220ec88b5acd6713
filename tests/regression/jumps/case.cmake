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
cgcm_run(SANITIZE)
cgcm_check(SANITIZE COMMAND ${check} jumps ${run}/load_curve.csv --expected 2 --contact-gap 0.02)
# Every row written is converged (residual below 1e-10) and summary.txt says "completed".
cgcm_check(AS converged SANITIZE COMMAND ${check} converged ${run}/load_curve.csv --tolerance 1e-10 --summary ${run}/summary.txt)
