# A run killed with SIGKILL leaves a results.e readable with the steps written
# so far (tests/tools/kill_midway.py; deck.xml: the default deck at level 1).
cgcm_test(SANITIZE COMMAND ${Python3_EXECUTABLE} ${CMAKE_SOURCE_DIR}/tests/tools/kill_midway.py --cgcm $<TARGET_FILE:cgcm>
                           --exo-compare $<TARGET_FILE:exo_compare> --output ${run} -- ${case_dir}/deck.xml ${quiet})
