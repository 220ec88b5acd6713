# Debian's Amesos2 KLU2 is wrong on several ranks: asking for it (deck.xml, the
# block of ../block) on two ranks must stop the run.
cgcm_test(SERIAL PASS "Amesos2 KLU2\" runs on one MPI rank only"
          COMMAND ${CGCM_MPIEXEC} -np 2 $<TARGET_FILE:cgcm> ${case_dir}/deck.xml Output/Directory=${run})
