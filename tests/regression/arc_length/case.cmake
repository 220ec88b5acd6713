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
# This case runs nothing: it compares the runs of ../arc_length_loop and ../jumps.
cgcm_check(AS agrees_with_displacement_control FIXTURES regression_jumps regression_arc_length_loop
           COMMAND ${check} agree ${out}/regression_arc_length_loop/load_curve.csv ${out}/regression_jumps/load_curve.csv
                   --at 0.01 -0.04 --tolerance 0 --abs 2e-10)
cgcm_check(AS folds_are_the_jumps FIXTURES regression_jumps regression_arc_length_loop
           COMMAND ${check} foldsmatch ${out}/regression_arc_length_loop/load_curve.csv
                   ${out}/regression_jumps/load_curve.csv --tolerance 1e-8)
