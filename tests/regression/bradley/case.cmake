# Very stiff bodies, gammaL = 100: pull-off on retraction -> Bradley -2 pi w R
# (w = f_w / (gammaL gammaW)), within 3 % (the polygonal sphere at R/r0 = 100 gives -0.987).
cgcm_run()
cgcm_check(COMMAND ${check} pulloff ${run}/load_curve.csv --expected=-6.0851e-7 --retraction --tolerance 0.03)
