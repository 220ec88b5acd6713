# 3D on the built-in hexahedral quarter model with quadratic cells (HEX27 at Mesh Refinement -1, the
# meridian cells twice those of level 0, 4 azimuthal cells at level 0, i.e. 2: 6426 nodes, 19 278
# unknowns, as many as the linear level-0 model; Method 3 on the curved QUAD9 facets) against the
# axisymmetric benchmark converged (QUAD9 at level 1: P_min -5.5964e-4 at u = -0.0015,
# P(0.06) = 1.007114e-2, dP/du on [0.05, 0.06] = 0.260467). Measured: P_min -0.25 %, P(0.06)
# +0.04 %, dP/du -0.40 %; the linear HEX8 model with the same nodes (../3d_sphere_hex) is 2.2 % weaker
# at P_min. Tolerances: 0.5 % for P_min and 1 % for the compressive branch, as 3d_sphere_quadratic.
cgcm_run()
cgcm_check(AS pmin COMMAND ${check} value ${run}/load_curve.csv --u -0.0015 --expected=-5.5964e-4 --tolerance 0.005)
cgcm_check(AS compression COMMAND ${check} value ${run}/load_curve.csv --u 0.06 --expected=1.007114e-2 --tolerance 0.01)
cgcm_check(AS stiffness COMMAND ${check} stiffness ${run}/load_curve.csv --from 0.05 --to 0.06 --expected=0.260467
                                --tolerance 0.01)
cgcm_check(AS converged COMMAND ${check} converged ${run}/load_curve.csv --tolerance 1e-10 --summary ${run}/summary.txt)
