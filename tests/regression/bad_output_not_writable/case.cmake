# An output folder that cannot be written (/proc, in deck.xml): exit code 2
# before any work, naming the file.
cgcm_app_check(SANITIZE ARGS ${case_dir}/deck.xml EXIT 2 STDERR "cannot write \"/proc/parameters.xml\"")
