# --restart refuses what it cannot continue, naming why (exit code 2):
# a run under arc-length control (deck.xml, run first).
cgcm_app_check(SANITIZE PRE_ARGS ${case_dir}/deck.xml Output/Directory=${run} ${quiet} ARGS --restart ${run} EXIT 2
               STDERR "cgcm: error: --restart .*only runs under displacement control")
