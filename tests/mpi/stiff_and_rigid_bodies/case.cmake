# A rigid half-space under a sphere twice as stiff as Material (deck.xml is a
# link to the default deck; a shorter path): the rigid body's conditions, its
# whole-body force and the stiffer body's weighted residual on two ranks give
# the one-rank curve (measured: equal to the digits written).
set(args "Bodies/half-space/Rigid=true" "Bodies/sphere/Young's Modulus=2" "Loading/Approach Path={-0.02, 0.03}"
    Output/Exodus=false)
cgcm_run(AS np1 ARGS ${args})
cgcm_run(AS np2 RANKS 2 ARGS ${args})
cgcm_check(AS np1_vs_np2 FIXTURES ${name}_np1 ${name}_np2
           COMMAND ${compare_csv} ${run}_np1/load_curve.csv ${run}_np2/load_curve.csv
                   --columns u,P,P_lower --rel 1e-8 --abs 1e-12)
