# ../3d_two_spheres on the same path under arc-length control (LOCA in 3D):
# the same state at its end (1e-6).
cgcm_run()
cgcm_check(FIXTURES regression_3d_two_spheres ${name}
           COMMAND ${check} agree ${out}/regression_3d_two_spheres/load_curve.csv ${run}/load_curve.csv --at 0.002
                   --tolerance 1e-6)
