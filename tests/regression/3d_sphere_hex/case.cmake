# 3D on the built-in hexahedral quarter model (inputs/3d/sphere-on-half-space-hex.xml at 4 cells
# over the quarter, 6426 nodes) against the axisymmetric default deck (the run of ../default_deck)
# at the same u, on the approach through P_min into contact.
# P_min's state (u = -0.0015): measured 2.2 % weaker than axisymmetry; the sphere's facets are
# chords between nodes on it, 4 over the quarter here: at a radius r from the axis they lie
# r^2 (pi / 8)^2 / (8 R) higher than the sphere, 0.8e-3 = 4 % of r0 at r = 0.2, where the adhesive
# force is gathered. Tolerance 3 %.
cgcm_run(SANITIZE)
cgcm_check(SANITIZE FIXTURES regression_3d_sphere_hex regression_default_deck
           COMMAND ${check} agree ${run}/load_curve.csv ${out}/regression_default_deck/load_curve.csv --at -0.0015
                   --tolerance 0.03)
# In contact (u = 0.0205, P = 1.527e-3): measured 0.28 % below axisymmetry; the contact is carried by
# the bulk, whose hexahedra are as fine as the meridian mesh's quadrilaterals. Tolerance 0.5 %.
cgcm_check(AS in_contact SANITIZE FIXTURES regression_3d_sphere_hex regression_default_deck
           COMMAND ${check} agree ${run}/load_curve.csv ${out}/regression_default_deck/load_curve.csv --at 0.0205
                   --tolerance 0.005)
# Every row written is converged (residual below 1e-10) and summary.txt says "completed".
cgcm_check(AS converged SANITIZE COMMAND ${check} converged ${run}/load_curve.csv --tolerance 1e-10 --summary ${run}/summary.txt)
