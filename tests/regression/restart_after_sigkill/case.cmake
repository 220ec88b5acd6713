# A run killed with SIGKILL halfway and continued with `cgcm --restart` from
# its checkpoint ends on the curve of an uninterrupted run
# (tests/tools/kill_and_restart.py; deck.xml is a link to the default deck;
# measured: identical to the last digit; the tolerance allows round-off from a
# matrix graph rebuilt at the restart).
cgcm_test(SANITIZE COMMAND ${Python3_EXECUTABLE} ${CMAKE_SOURCE_DIR}/tests/tools/kill_and_restart.py --cgcm $<TARGET_FILE:cgcm>
                           --exo-compare $<TARGET_FILE:exo_compare> --output ${run} --at 0.5 -- ${case_dir}/deck.xml ${quiet})
