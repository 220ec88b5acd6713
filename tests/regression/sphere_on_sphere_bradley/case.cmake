# Sphere on sphere, R1 = R2: ../bradley with the reduced radius R0/2,
# -pi w R0 = -3.04255e-7, within 3 %.
cgcm_run()
cgcm_check(COMMAND ${check} pulloff ${run}/load_curve.csv --expected=-3.04255e-7 --retraction --tolerance 0.03)
