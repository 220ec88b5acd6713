# Method 1 on a symmetric part: the quarter model of the 3D sphere deck (its
# "symmetry x" and "symmetry y" planes; the other three quarters act through
# image cells) and the whole model mirrored from the same mesh (node for node
# symmetric) give the same curve, to 1e-7 of P (Newton's tolerance on two
# different systems; the quarter's P is 4 x its resultant). A coarse mesh,
# order-1 quadrature and a 3 r0 cutoff keep it short: this compares the two
# models, not the accuracy.
cgcm_run(AS quarter DECK deck-quarter.xml)
cgcm_run(AS whole DECK deck-whole.xml)
cgcm_check(AS quarter_vs_whole FIXTURES ${name}_quarter ${name}_whole
           COMMAND ${compare_csv} ${run}_quarter/load_curve.csv ${run}_whole/load_curve.csv --columns u,P,gap --rel 1e-7 --abs 1e-12)
