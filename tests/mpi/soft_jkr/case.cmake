# The soft sphere of tests/regression/soft_jkr (jump-in, ring snaps, pull-off,
# each jump by relaxation and fold location by continuation; deck.xml is a link
# to its deck) on two ranks with the iterative solver: the same states, folds
# and jumps as on one rank with KLU2 (1e-7).
cgcm_run(AS np2 RANKS 2)
cgcm_check(AS np1_vs_np2 FIXTURES regression_soft_jkr ${name}_np2
           COMMAND ${compare_csv} ${outputs}/regression/regression_soft_jkr/load_curve.csv ${run}_np2/load_curve.csv
                   --columns u,P,gap,P_lower,fold,jump --rel 1e-7 --abs 1e-10)
