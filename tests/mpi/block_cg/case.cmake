# The block of ../block with CG + MueLu, the Dirichlet rows eliminated
# symmetrically: np = 1 and np = 2 give the same load curve (1e-8), and so do
# CG and GMRES (../block's np = 1 run).
cgcm_run(AS np1 PRINT_STEPS)
cgcm_run(AS np2 RANKS 2 PRINT_STEPS)
cgcm_check(AS np1_vs_np2 FIXTURES ${name}_np1 ${name}_np2
           COMMAND ${compare_csv} ${run}_np1/load_curve.csv ${run}_np2/load_curve.csv --columns u,P --rel 1e-8 --abs 1e-12)
cgcm_check(AS vs_gmres FIXTURES mpi_block_np1 ${name}_np1
           COMMAND ${compare_csv} ${out}/mpi_block_np1/load_curve.csv ${run}_np1/load_curve.csv --columns u,P --rel 1e-8
                   --abs 1e-12)
