# A soft sphere in the JKR regime (gammaL = 100, gammaW = 4.07: Maugis-Dugdale
# lambda = 5), mesh level 0, displacement control: it jumps into contact at
# the first fold, the contact zone grows and shrinks ring by ring (small snaps,
# jump = 1 without a fold), and it pulls off at the second fold beyond the
# start gap. Both folds are located, every row is converged.
cgcm_run()
cgcm_check(COMMAND ${check} folds ${run}/load_curve.csv --expected 2 --contact-gap 0.01)
cgcm_check(AS converged COMMAND ${check} converged ${run}/load_curve.csv --tolerance 1e-10 --summary ${run}/summary.txt)
