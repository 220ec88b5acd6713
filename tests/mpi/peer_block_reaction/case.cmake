# The peer block (tests/regression/peer_block_reaction: bench_peer_block, no
# deck) on two ranks: the same top reaction as dolfinx 0.5.2's,
# -0.11253130711878, to 1e-10.
cgcm_test(AS np2 SERIAL PASS "\"converged\": true.*\"unconverged_solves\": 0.*\"reaction\": -0.112531307[0-2]"
          COMMAND ${CGCM_MPIEXEC} -np 2 $<TARGET_FILE:bench_peer_block> 8)
