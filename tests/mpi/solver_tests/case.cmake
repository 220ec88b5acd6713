# The physics unit tests again (solver_tests), on a distributed system: two ranks.
cgcm_test(AS np2 SERIAL COMMAND ${CGCM_MPIEXEC} -np 2 $<TARGET_FILE:solver_tests>)
