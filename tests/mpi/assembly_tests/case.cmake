# The physics unit tests again (assembly_tests), on a distributed system: two ranks.
cgcm_test(AS np2 SERIAL COMMAND ${CGCM_MPIEXEC} -np 2 $<TARGET_FILE:assembly_tests>)
