# The set-up rank 0 builds and sends, and the results, on two ranks (app_tests;
# not the checkpoint tests: both ranks would write one file).
cgcm_test(AS np2 SERIAL COMMAND ${CGCM_MPIEXEC} -np 2 $<TARGET_FILE:app_tests> --gtest_filter=Setup.*:Results.*)
