# Inhomogeneous large compression of a block (the loaded face cannot slide,
# distorted cells; deck.xml): the np = 1 and np = 2 runs give the same load
# curve (1e-8), with the same iterative solver on both rank counts.
cgcm_run(AS np1 PRINT_STEPS)
cgcm_run(AS np2 RANKS 2 PRINT_STEPS)
cgcm_check(AS np1_vs_np2 FIXTURES ${name}_np1 ${name}_np2
           COMMAND ${compare_csv} ${run}_np1/load_curve.csv ${run}_np2/load_curve.csv --columns u,P --rel 1e-8 --abs 1e-12)
