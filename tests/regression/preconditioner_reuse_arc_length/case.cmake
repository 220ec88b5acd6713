# ../3d_two_spheres_arc_length (LOCA's arc-length steps in 3D, GMRES + MueLu) with the preconditioner kept
# for three later Jacobians, across steps and graph restarts: the same path, row by row. Every solve meets
# the linear tolerance (1e-10) with the current Jacobian, so the states differ by round-off of the solves:
# u, P and gap to 1e-6 relative, 1e-10 absolute (the tolerance of 3d_two_spheres_arc_length's own check).
cgcm_run(DECK ../3d_two_spheres_arc_length/deck.xml ARGS "Solver/Linear Solver/Preconditioner Reuse=3")
cgcm_check(FIXTURES regression_3d_two_spheres_arc_length ${name}
           COMMAND ${compare_csv} ${out}/regression_3d_two_spheres_arc_length/load_curve.csv ${run}/load_curve.csv
                   --columns u,P,gap --rel 1e-6 --abs 1e-10)
