# Method 3 on quadratic cells (QUAD9: each rank's points on its own curved segments, projected
# onto every body's curved segments; deck.xml: the default deck with Geometry/Element Order = 2,
# approach to u = -0.004, MUMPS on both rank counts): np = 1 and np = 2
# give the same curve (1e-7) and the same results.e.
cgcm_run(AS np1)
cgcm_run(AS np2 RANKS 2)
cgcm_check(AS np1_vs_np2 FIXTURES ${name}_np1 ${name}_np2
           COMMAND ${compare_csv} ${run}_np1/load_curve.csv ${run}_np2/load_curve.csv --columns u,P,gap,P_lower
                   --rel 1e-7 --abs 1e-12)
cgcm_check(AS results_np1_vs_np2 FIXTURES ${name}_np1 ${name}_np2
           COMMAND exo_compare --rel 1e-7 --abs 1e-10 ${run}_np1/results.e ${run}_np2/results.e)
