# LOCA's bordered solves through CG with the Dirichlet rows eliminated
# symmetrically (arc-length control of the block of
# inputs/examples/block-compression.xml, where the prescribed displacement
# moves with the continuation parameter; deck-cg.xml) give MUMPS' curve
# (deck-mumps.xml), to 1e-8.
# (PRINT_STEPS: the runs print their steps in the test log, as they always did)
cgcm_run(AS cg DECK deck-cg.xml PRINT_STEPS)
cgcm_run(AS mumps DECK deck-mumps.xml PRINT_STEPS)
cgcm_check(AS cg_vs_mumps FIXTURES ${name}_cg ${name}_mumps
           COMMAND ${compare_csv} ${run}_cg/load_curve.csv ${run}_mumps/load_curve.csv --columns u,P --rel 1e-8 --abs 1e-12)
