# Three spheres on a substrate in 3D (tests/regression/three_spheres: mirrored
# mesh, several bodies, body forces; deck.xml is a link to its deck) on two
# ranks: the same curve and the same force on every body as on one rank (1e-7;
# both GMRES + MueLu, the 3D default).
cgcm_run(AS np2 RANKS 2)
cgcm_check(AS np1_vs_np2 FIXTURES regression_three_spheres ${name}_np2
           COMMAND ${compare_csv} ${outputs}/regression/regression_three_spheres/load_curve.csv
                   ${run}_np2/load_curve.csv --columns u,P,P_lower --rel 1e-7 --abs 1e-12)
cgcm_check(AS body_forces_np1_vs_np2 FIXTURES regression_three_spheres ${name}_np2
           COMMAND ${compare_csv} ${outputs}/regression/regression_three_spheres/body_forces.csv
                   ${run}_np2/body_forces.csv --columns u,body,Fx,Fy,Fz --rel 1e-7 --abs 1e-12)
