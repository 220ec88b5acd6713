# A two-rank run killed with SIGKILL halfway and continued with --restart on two
# ranks ends on the curve, body forces and results.e of an uninterrupted two-rank
# run (the state streamed to rank 0 by global dof as it writes checkpoint.bin,
# each rank reading its own entries back, each on its part of the mesh;
# tests/tools/kill_and_restart.py; deck.xml is a link to the default deck).
string(JOIN " " two_ranks ${CGCM_MPIEXEC} -np 2)
cgcm_test(AS np2 SERIAL
          COMMAND ${Python3_EXECUTABLE} ${CMAKE_SOURCE_DIR}/tests/tools/kill_and_restart.py --cgcm $<TARGET_FILE:cgcm>
                  --exo-compare $<TARGET_FILE:exo_compare> --output ${run}_np2 --at 0.5 --launcher ${two_ranks}
                  -- ${case_dir}/deck.xml ${quiet})
# The same run continued on one rank: the curve and results.e of the two-rank run to 1e-7, as one
# and two ranks agree (cgcm_ranks_agree), and 1e-10 absolute for the round-off of the residuals.
cgcm_test(AS np2_restart_np1 SERIAL
          COMMAND ${Python3_EXECUTABLE} ${CMAKE_SOURCE_DIR}/tests/tools/kill_and_restart.py --cgcm $<TARGET_FILE:cgcm>
                  --exo-compare $<TARGET_FILE:exo_compare> --output ${run}_np2_restart_np1 --at 0.5
                  --rel 1e-7 --abs 1e-10 --launcher ${two_ranks} --restart-launcher=
                  -- ${case_dir}/deck.xml ${quiet})
# And a one-rank run continued on two: each rank reads its own entries of the one-rank checkpoint.
cgcm_test(AS np1_restart_np2 SERIAL
          COMMAND ${Python3_EXECUTABLE} ${CMAKE_SOURCE_DIR}/tests/tools/kill_and_restart.py --cgcm $<TARGET_FILE:cgcm>
                  --exo-compare $<TARGET_FILE:exo_compare> --output ${run}_np1_restart_np2 --at 0.5
                  --rel 1e-7 --abs 1e-10 --launcher= --restart-launcher ${two_ranks}
                  -- ${case_dir}/deck.xml ${quiet})
