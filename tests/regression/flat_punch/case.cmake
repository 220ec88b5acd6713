# The rigid flat punch of inputs/flat-punch.xml (deck.xml is a copy of it, its mesh file found from here) at
# a = 0.047 critical sizes: the strength-limited end, where the pull-off is
# the strength times the face (Gao & Yao 2004): pi a^2 sigma_max = 4.904e-3
# axisymmetric, 2 a sigma_max = 3.122e-3 per unit thickness for the strip in
# plane strain. Tolerance 3 %: the face is not loaded quite uniformly at a
# finite a/a_cr (measured: 0.5 % and 0.8 % below).
cgcm_run(AS axisymmetric ARGS Output/Exodus=false)
cgcm_check(AS axisymmetric_pulloff FIXTURES ${name}_axisymmetric
           COMMAND ${check} pulloff ${run}_axisymmetric/load_curve.csv --retraction --expected=-4.904e-3 --tolerance 0.03)
cgcm_run(AS plane_strain ARGS "Problem/Formulation=plane strain" Output/Exodus=false)
cgcm_check(AS plane_strain_pulloff FIXTURES ${name}_plane_strain
           COMMAND ${check} pulloff ${run}_plane_strain/load_curve.csv --retraction --expected=-3.122e-3 --tolerance 0.03)
