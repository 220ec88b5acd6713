# --check on a bad deck: the error and exit code 2 of a run.
cgcm_app_check(SANITIZE ARGS --check ${case_dir}/deck.xml EXIT 2
               STDERR "cgcm: error: Material/Poisson's Ratio = 0.5: out of range")
