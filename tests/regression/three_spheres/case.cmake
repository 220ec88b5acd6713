# Three spheres on a substrate (inputs/3d/three-spheres.xml, mirrored mesh, a
# coarser mesh and a short path into adhesive contact and back; the outer
# spheres twice as stiff through Bodies/outer sphere, which the mirror image
# inherits): the outer spheres' forces are mirror images to round-off, the
# lateral forces of all bodies sum to zero by symmetry, and the vertical ones
# within Method 3's force imbalance (each body integrates over its own
# surface: 2.1 % here, as P against P_lower, also checked), 3 %.
cgcm_run()
cgcm_check(COMMAND ${check} bodies ${run}/body_forces.csv --mirror 1 3 --axis x --zero x y --mirror-tolerance 1e-9
                   --zero-tolerance 1e-9 --balance-tolerance 0.03)
cgcm_check(AS balance COMMAND ${check} balance ${run}/load_curve.csv --tolerance 0.03)
# Every row written is converged (residual below 1e-10) and summary.txt says "completed".
cgcm_check(AS converged COMMAND ${check} converged ${run}/load_curve.csv --tolerance 1e-10 --summary ${run}/summary.txt)
