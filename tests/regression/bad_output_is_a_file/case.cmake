# The output folder is an existing file (the default deck itself; deck.xml is a
# link to it): exit code 2 before any work, naming the folder and why.
cgcm_app_check(SANITIZE ARGS ${case_dir}/deck.xml Output/Directory=${CMAKE_SOURCE_DIR}/inputs/sphere-on-half-space.xml
               EXIT 2 STDERR "Output/Directory = \"[^\"]*sphere-on-half-space.xml\": cannot create it \\(Not a directory")
