# Repulsive-only potential, small approach (a/R <= 0.11): Hertz,
# P = (4/3) E* sqrt(R) delta^1.5 with E* = Y / (2 (1 - nu^2)), within 3 %.
cgcm_run(SANITIZE)
cgcm_check(SANITIZE COMMAND ${check} hertz ${run}/load_curve.csv --modulus 0.5208333333 --radius 1 --u-min 0.003
                            --u-max 0.012 --tolerance 0.03)
