# 3D: the default deck's physics on a tetrahedral quarter model
# (inputs/3d/sphere-on-half-space.xml, the mesh's defaults: 1955 nodes). The
# approach up to P_min against the axisymmetric reference on the same path
# (P_min on approach -5.5862e-4 at u = -0.0015; measured -5.5837e-4), 0.5 %.
cgcm_run(SANITIZE)
cgcm_check(SANITIZE COMMAND ${check} pulloff ${run}/load_curve.csv --expected=-5.5862e-4 --tolerance 0.005)
# Every row written is converged (residual below 1e-10) and summary.txt says "completed".
cgcm_check(AS converged SANITIZE COMMAND ${check} converged ${run}/load_curve.csv --tolerance 1e-10 --summary ${run}/summary.txt)
