# The sphere-on-half-space benchmark (interaction pairs, graph couplings and
# their owners across ranks; deck.xml: a short path into contact and back, the
# same iterative solver on both rank counts): np = 1 and np = 2 give the same
# curve (1e-7)...
cgcm_run(AS np1 PRINT_STEPS)
cgcm_run(AS np2 RANKS 2 PRINT_STEPS)
cgcm_check(AS np1_vs_np2 FIXTURES ${name}_np1 ${name}_np2
           COMMAND ${compare_csv} ${run}_np1/load_curve.csv ${run}_np2/load_curve.csv --columns u,P,gap,P_lower
                   --rel 1e-7 --abs 1e-12)
# ... and the same results.e: the ranks stream their parts to rank 0, which writes one file
# (the residuals, round-off, differ below the tolerance's absolute part).
cgcm_check(AS results_np1_vs_np2 FIXTURES ${name}_np1 ${name}_np2
           COMMAND exo_compare --rel 1e-7 --abs 1e-10 ${run}_np1/results.e ${run}_np2/results.e)
