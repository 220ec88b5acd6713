# The spheres of ../3d_two_spheres driven by Geometry/Drive Vector = {0, 0, -1}
# (every component of "driven" prescribed, u the plain displacement:
# u = 0.0372645 is the benchmark's u = 0): the P_min of the vertical drive
# (-2.8430e-4, measured in ../3d_two_spheres; measured here -2.84315e-4), 0.1 %.
cgcm_run()
cgcm_check(COMMAND ${check} pulloff ${run}/load_curve.csv --expected=-2.8430e-4 --tolerance 0.001)
