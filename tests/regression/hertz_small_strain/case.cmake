# Hertz as in ../hertz with Material/Kinematics = small strain (linear
# elasticity on the reference configuration, Hertz's own assumption), within
# 1 %: measured 1.0013 against 0.9959 at finite strain.
cgcm_run(SANITIZE)
cgcm_check(SANITIZE COMMAND ${check} hertz ${run}/load_curve.csv --modulus 0.5208333333 --radius 1 --u-min 0.003
                            --u-max 0.012 --tolerance 0.01)
