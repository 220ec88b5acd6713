# Plane strain (cylinder on half-space): runs through approach and retraction,
# and the forces on the two bodies balance to 3 %.
cgcm_run(SANITIZE)
cgcm_check(SANITIZE COMMAND ${check} balance ${run}/load_curve.csv --tolerance 0.03)
