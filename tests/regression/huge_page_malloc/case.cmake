# glibc's malloc in transparent huge pages: cgcm sets the tunable and runs
# itself again (core/HugePages.hpp), and the summary says which pages it had;
# with CGCM_HUGE_PAGES=0, 4 KiB pages.
cgcm_test(PASS "peak memory per rank: [0-9]+ MB \\(malloc in transparent huge pages\\)"
          COMMAND cgcm ${case_dir}/deck.xml Output/Directory=${run})
cgcm_test(AS off ENVIRONMENT CGCM_HUGE_PAGES=0 PASS "peak memory per rank: [0-9]+ MB \\(malloc in 4 KiB pages\\)"
          COMMAND cgcm ${case_dir}/deck.xml Output/Directory=${run}_off)
