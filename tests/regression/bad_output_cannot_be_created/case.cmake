# An output folder that cannot be created (/proc/cgcm/out, in deck.xml):
# exit code 2 before any work, naming the folder.
cgcm_app_check(SANITIZE ARGS ${case_dir}/deck.xml EXIT 2 STDERR "Output/Directory = \"/proc/cgcm/out\": cannot create it")
