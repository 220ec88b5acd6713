# Soft spheres, strong adhesion: theoretical lambda = 3 (Tabor mu = 2.6),
# gammaL = 800, gammaW = 24.8 (deck.xml is a link to
# inputs/validation/jkr-limit.xml: that deck, as it is): approach
# through the jump-to-contact (found by continuation), then retract. The
# minimum force on retraction against the Lennard-Jones sphere reference at
# the same mu (cgcm-analytic ljsphere: -1.5613 pi w R = -2.3943e-4), within
# 1.5 %: measured +0.52 % (the surface density beta0 over the current area
# gave +2.7 %, doc/theory.md#surface-density); the rest of the 1.5 % is the
# 1 % sawtooth of P(u) on this mesh (cells of l/3, doc/validation.md). The
# reference itself tends to JKR's -1.5 pi w R (-1.5092 at mu = 10, checked
# within 2 % in analytic_tests; -1.5030 at mu = 20).
cgcm_run()
cgcm_check(COMMAND ${check} pulloff ${run}/load_curve.csv --expected=-2.3943e-4 --retraction --tolerance 0.015)
# and the measured value itself (-1.5694 pi w R, doc/validation.md), 0.5 %
cgcm_check(AS value COMMAND ${check} pulloff ${run}/load_curve.csv --expected=-2.4068e-4 --retraction --tolerance 0.005)
