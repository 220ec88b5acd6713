# glibc's malloc tuned for the run: cgcm sets the tunables (transparent huge
# pages, blocks from 4 MiB mapped) and runs itself again
# (core/MallocTunables.hpp); the summary says what it ran with. Each is turned
# off by its variable, and a value the environment already sets is kept.
cgcm_test(PASS "peak memory per rank: [0-9]+ MB \\(malloc in transparent huge pages, blocks from 4 MiB mapped\\)"
          COMMAND cgcm ${case_dir}/deck.xml Output/Directory=${run})
cgcm_test(AS small_pages ENVIRONMENT CGCM_HUGE_PAGES=0
          PASS "peak memory per rank: [0-9]+ MB \\(malloc in 4 KiB pages, blocks from 4 MiB mapped\\)"
          COMMAND cgcm ${case_dir}/deck.xml Output/Directory=${run}_small_pages)
cgcm_test(AS moving_threshold ENVIRONMENT CGCM_MMAP_THRESHOLD=0
          PASS "peak memory per rank: [0-9]+ MB \\(malloc in transparent huge pages\\)"
          COMMAND cgcm ${case_dir}/deck.xml Output/Directory=${run}_moving_threshold)
cgcm_test(AS environment_kept ENVIRONMENT GLIBC_TUNABLES=glibc.malloc.mmap_threshold=1048576
          PASS "peak memory per rank: [0-9]+ MB \\(malloc in transparent huge pages, blocks from 1 MiB mapped\\)"
          COMMAND cgcm ${case_dir}/deck.xml Output/Directory=${run}_environment_kept)
cgcm_test(AS glibc_defaults ENVIRONMENT CGCM_HUGE_PAGES=0 CGCM_MMAP_THRESHOLD=0
          PASS "peak memory per rank: [0-9]+ MB \\(malloc in 4 KiB pages\\)"
          COMMAND cgcm ${case_dir}/deck.xml Output/Directory=${run}_glibc_defaults)
cgcm_test(AS huge_pages_off_in_environment ENVIRONMENT GLIBC_TUNABLES=glibc.malloc.hugetlb=0
          PASS "peak memory per rank: [0-9]+ MB \\(malloc in 4 KiB pages, blocks from 4 MiB mapped\\)"
          COMMAND cgcm ${case_dir}/deck.xml Output/Directory=${run}_huge_pages_off_in_environment)
