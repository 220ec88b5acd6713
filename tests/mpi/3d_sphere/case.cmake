# The 3D sphere on half-space (tests/regression/3d_sphere: one body over a
# substrate, tetrahedra, geometric partition, each rank searching from its own
# facets; deck.xml is a link to its deck) on two ranks: the one-rank curve to
# solver tolerance (1e-7)...
cgcm_run(AS np2 RANKS 2)
cgcm_check(AS np1_vs_np2 FIXTURES regression_3d_sphere ${name}_np2
           COMMAND ${compare_csv} ${outputs}/regression/regression_3d_sphere/load_curve.csv ${run}_np2/load_curve.csv
                   --columns u,P,gap,contact_radius,P_lower --rel 1e-7 --abs 1e-12)
# ... and the same results.e, the interaction traction included (each rank's
# pairs summed on rank 0).
cgcm_check(AS results_np1_vs_np2 FIXTURES regression_3d_sphere ${name}_np2
           COMMAND exo_compare --rel 1e-7 --abs 1e-10 ${outputs}/regression/regression_3d_sphere/results.e
                   ${run}_np2/results.e)
# Three ranks: rank 0 cuts and sends two parts, one after the other (oversubscribed on two cores).
cgcm_run(AS np3 RANKS 3)
cgcm_check(AS np1_vs_np3 FIXTURES regression_3d_sphere ${name}_np3
           COMMAND ${compare_csv} ${outputs}/regression/regression_3d_sphere/load_curve.csv ${run}_np3/load_curve.csv
                   --columns u,P,gap,contact_radius,P_lower --rel 1e-7 --abs 1e-12)
cgcm_check(AS results_np1_vs_np3 FIXTURES regression_3d_sphere ${name}_np3
           COMMAND exo_compare --rel 1e-7 --abs 1e-10 ${outputs}/regression/regression_3d_sphere/results.e
                   ${run}_np3/results.e)
