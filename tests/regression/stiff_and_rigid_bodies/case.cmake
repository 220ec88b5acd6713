# Stiffness contrast (deck.xml is a link to the default deck). A body 1e6 or
# 1e9 times stiffer than the other follows the whole path (the stress is formed
# from the displacement gradient, and the stiffer body's residual counts in its
# own force unit), and lands on the curve of the same body made rigid
# (Bodies/<name>/Rigid). Tolerances: the compliance of the stiff body relative
# to the soft one is 1/Y, so P differs by about P_max/Y (measured: 2.5e-8 for
# the 1e6 half-space, 2e-11 for the 1e9 sphere, P_max = 0.0215); the bounds are
# twice that, and a relative 1e-5 (resp. 1e-7) where P is large. The row
# counts and u must agree: both runs follow the same path.
cgcm_run(AS half_space_stiff ARGS "Bodies/half-space/Young's Modulus=1e6" Output/Exodus=false)
cgcm_run(AS half_space_rigid SANITIZE ARGS "Bodies/half-space/Rigid=true" Output/Exodus=false)
cgcm_check(AS half_space FIXTURES ${name}_half_space_stiff ${name}_half_space_rigid
           COMMAND ${compare_csv} ${run}_half_space_stiff/load_curve.csv ${run}_half_space_rigid/load_curve.csv
                   --columns u,P,P_lower --rel 1e-5 --abs 5e-8)
cgcm_run(AS sphere_stiff ARGS "Bodies/sphere/Young's Modulus=1e9" Output/Exodus=false)
cgcm_run(AS sphere_rigid ARGS "Bodies/sphere/Rigid=true" Output/Exodus=false)
cgcm_check(AS sphere FIXTURES ${name}_sphere_stiff ${name}_sphere_rigid
           COMMAND ${compare_csv} ${run}_sphere_stiff/load_curve.csv ${run}_sphere_rigid/load_curve.csv
                   --columns u,P,P_lower --rel 1e-7 --abs 4e-11)
