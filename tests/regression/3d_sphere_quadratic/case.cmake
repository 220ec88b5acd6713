# 3D on quadratic tetrahedra (TETRA10 from meshes/sphere-on-half-space-3d.geo at contact cells of
# 0.08, twice the linear deck's: 4247 nodes, 12 741 unknowns; Method 3 on the curved TRI6 facets)
# against the axisymmetric benchmark converged (QUAD9 at level 1, within 1e-5 of the extrapolated
# curve: P_min -5.5964e-4 at u = -0.0015, P(0.06) = 1.007114e-2, dP/du on [0.05, 0.06] = 0.260467).
# Measured: P_min -0.34 %, P(0.06) +0.42 %, dP/du +0.07 %; the linear tetrahedra of the shipped
# deck (1955 nodes) are 4.4 % stiffer in compression. Tolerances: 0.5 % for P_min and 1 % for the
# compressive branch, the accuracy asked of a 3D quadratic run at <= 30k unknowns.
cgcm_run()
cgcm_check(AS pmin COMMAND ${check} value ${run}/load_curve.csv --u -0.0015 --expected=-5.5964e-4 --tolerance 0.005)
cgcm_check(AS compression COMMAND ${check} value ${run}/load_curve.csv --u 0.06 --expected=1.007114e-2 --tolerance 0.01)
cgcm_check(AS stiffness COMMAND ${check} stiffness ${run}/load_curve.csv --from 0.05 --to 0.06 --expected=0.260467
                                --tolerance 0.01)
cgcm_check(AS converged COMMAND ${check} converged ${run}/load_curve.csv --tolerance 1e-10 --summary ${run}/summary.txt)
