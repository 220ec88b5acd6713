# Bad input stops with exit code 2 before any solving, with a message naming the problem.
# Two bodies drawn into each other (overlap.geo).
cgcm_bad_input(SANITIZE REGEX "overlap.geo.*bodies overlap.*body \"upper\".*body \"lower\"")
