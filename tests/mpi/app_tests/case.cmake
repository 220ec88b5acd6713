# The set-up rank 0 builds and sends, the results, and the whole runs of block
# decks, on two ranks (app_tests).
cgcm_test(AS np2 SERIAL COMMAND ${CGCM_MPIEXEC} -np 2 $<TARGET_FILE:app_tests>
          --gtest_filter=Setup.*:Results.*:LoadStepping.*:LinearSolver.*:Input.*)
