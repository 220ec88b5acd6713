# gmsh geometry: meshes/sphere-on-half-space.geo is the built-in mesh node for
# node, so the default deck gives the built-in curve (P_min within 0.5 % of
# the reference, and every row to 1e-8 of the built-in run).
# Here: P_min (../gmsh_same_curve_as_built_in compares the curves).
cgcm_run(SANITIZE)
cgcm_check(SANITIZE COMMAND ${check} pulloff ${run}/load_curve.csv --expected=-5.6355e-4 --tolerance 0.005)
