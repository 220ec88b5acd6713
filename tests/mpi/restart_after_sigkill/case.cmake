# A two-rank run killed with SIGKILL halfway and continued with --restart on two
# ranks ends on the curve, body forces and results.e of an uninterrupted two-rank
# run (the state gathered and scattered by global dof, each rank on its part of
# the mesh; tests/tools/kill_and_restart.py; deck.xml is a link to the default deck).
string(JOIN " " two_ranks ${CGCM_MPIEXEC} -np 2)
cgcm_test(AS np2 SERIAL
          COMMAND ${Python3_EXECUTABLE} ${CMAKE_SOURCE_DIR}/tests/tools/kill_and_restart.py --cgcm $<TARGET_FILE:cgcm>
                  --exo-compare $<TARGET_FILE:exo_compare> --output ${run}_np2 --at 0.5 --launcher ${two_ranks}
                  -- ${case_dir}/deck.xml ${quiet})
