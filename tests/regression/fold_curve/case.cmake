# The jump-in fold of the benchmark (gammaL = 50) followed in (u, gammaW) to
# its cusp, where the approach stops jumping (doc/validation.md, "The approach
# becomes stable"): the last row is the located cusp, gammaW = 42.0591, to 1e-5
# (it is located to solver tolerance; 1e-5 allows for round-off elsewhere).
# Independent check of the number: approaches at fixed gammaW with steps of
# 1e-4 (50 times finer than the map's) through the region of the fold: at
# gammaW = 41.8 (0.6 % below) the path has the jump-in loop, two folds 1.5e-6
# apart in u; at 42.3 (0.6 % above) none.
cgcm_run()
cgcm_check(COMMAND ${check} cusp ${run}/load_curve.csv --column gammaW --expected 42.0591 --tolerance 1e-5)
set(fixed LOCA/Bifurcation/Type=None Loading/Continuation\ Parameter=u "Loading/Parameter Path={}"
          "Loading/Approach Path={-0.03,-0.01}" Loading/Initial\ Increment=0.0001 Loading/Max\ Increment=0.0001)
cgcm_run(AS below ARGS ${fixed} Interaction/gammaW=41.8)
cgcm_check(AS below_has_the_loop FIXTURES ${name}_below COMMAND ${check} folds ${run}_below/load_curve.csv --expected 2)
cgcm_run(AS above ARGS ${fixed} Interaction/gammaW=42.3)
cgcm_check(AS above_has_none FIXTURES ${name}_above COMMAND ${check} folds ${run}_above/load_curve.csv --expected 0)
