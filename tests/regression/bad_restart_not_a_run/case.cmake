# --restart refuses what it cannot continue, naming why (exit code 2):
# a folder that is no run's.
cgcm_app_check(SANITIZE ARGS --restart ${out}/no-such-run EXIT 2
               STDERR "cgcm: error: --restart .*no-such-run: not the output folder of a run")
