# Bad input stops with exit code 2 before any solving, with a message naming the problem.
# A mesh file that does not exist.
cgcm_bad_input(SANITIZE REGEX "nothere.geo\" does not exist")
