# Two spheres in 3D (inputs/3d/two-spheres.xml, quarter model, 1402 nodes)
# against the axisymmetric "sphere on sphere" geometry on the same path
# (P_min -2.8482e-4 at u = -0.0015; measured -2.83776e-4), 1 %.
cgcm_run()
cgcm_check(COMMAND ${check} pulloff ${run}/load_curve.csv --expected=-2.8482e-4 --tolerance 0.01)
