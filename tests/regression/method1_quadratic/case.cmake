# Method 1 (Interaction/Method = volume pair) on quadratic cells (Geometry/Element Order = 2:
# QUAD9, the sphere's arc nodes on the circle), the method1_axisymmetric approach to u = 0 at
# level 0. The force at u = -0.0015 against an independent run, linear cells one level finer
# (method1_axisymmetric's deck with Geometry/Mesh Refinement = 1: -5.4963e-4; this deck measured
# -5.5264e-4, 0.55 % from it; linear level 0: -5.5079e-4): 1 %, the discretisations' difference.
# The forces on the two bodies balance to solver tolerance (1e-7: one energy), every row converged.
cgcm_run()
cgcm_check(COMMAND ${check} value ${run}/load_curve.csv --u -0.0015 --expected=-5.4963e-4 --tolerance 0.01)
cgcm_check(AS balance COMMAND ${check} balance ${run}/load_curve.csv --tolerance 1e-7)
cgcm_check(AS converged COMMAND ${check} converged ${run}/load_curve.csv --tolerance 1e-10 --summary ${run}/summary.txt)
