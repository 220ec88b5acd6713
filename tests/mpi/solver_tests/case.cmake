# The physics unit tests again (solver_tests), on a distributed system: two ranks
# (not the one-process checkpoint tests, Checkpoint.*: both ranks would write one file; the ranks'
# checkpoint, DistributedCheckpoint.*, runs).
cgcm_test(AS np2 SERIAL COMMAND ${CGCM_MPIEXEC} -np 2 $<TARGET_FILE:solver_tests> --gtest_filter=-Checkpoint.*)
