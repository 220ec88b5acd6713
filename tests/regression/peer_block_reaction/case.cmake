# The peer block of bench/peers/ (Neo-Hookean unit cube, 8^3 hex8, bottom clamped,
# top pressed down 10 %; bench_peer_block builds it, no deck): cgcm's top
# reaction equals dolfinx 0.5.2's on the same mesh, -0.11253130711878, to 1e-10
# (-0.112531307xx; both stop Newton at |f|_2 < 1e-9 and differ by 4e-12).
cgcm_test(PASS "\"converged\": true.*\"unconverged_solves\": 0.*\"reaction\": -0.112531307[0-2]"
          COMMAND bench_peer_block 8)
# The same with CG, the Dirichlet rows eliminated symmetrically (the default
# above is GMRES on the Jacobian with its unit rows).
cgcm_test(AS cg PASS "\"converged\": true.*\"unconverged_solves\": 0.*\"reaction\": -0.112531307[0-2]"
          COMMAND bench_peer_block 8 "Belos CG + MueLu")
