# Method 1 (volume pairs: each rank evaluates the directed cell pairs whose row
# cell it owns, the column cells' coordinates replicated; deck.xml: the default
# deck's approach to u = -0.004, the same iterative solver on both rank
# counts): np = 1 and np = 2 give the same curve on the approach (1e-7) and
# the same results.e, the interaction force on each node and the traction of
# the surface nodes included (each rank's pairs exported to the rows' owners,
# gathered on rank 0).
cgcm_run(AS np1)
cgcm_run(AS np2 RANKS 2)
cgcm_check(AS np1_vs_np2 FIXTURES ${name}_np1 ${name}_np2
           COMMAND ${compare_csv} ${run}_np1/load_curve.csv ${run}_np2/load_curve.csv --columns u,P,gap,P_lower
                   --rel 1e-7 --abs 1e-12)
cgcm_check(AS results_np1_vs_np2 FIXTURES ${name}_np1 ${name}_np2
           COMMAND exo_compare --rel 1e-7 --abs 1e-10 ${run}_np1/results.e ${run}_np2/results.e)
