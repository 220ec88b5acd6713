# Two spheres in 3D (inputs/3d/two-spheres.xml, quarter model, 1402 nodes)
# against the axisymmetric "sphere on sphere" geometry on the same path
# (P_min -2.8549e-4 at u = -0.0015; measured -2.8430e-4), 1 %.
cgcm_run()
cgcm_check(COMMAND ${check} pulloff ${run}/load_curve.csv --expected=-2.8549e-4 --tolerance 0.01)
