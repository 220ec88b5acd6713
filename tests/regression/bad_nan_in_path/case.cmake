# Bad input stops with exit code 2 before any solving, with a message naming the problem.
# Numbers that are not numbers stop before any work, with the parameter's path. Here: NaN
# in the approach path.
cgcm_bad_input(SANITIZE REGEX "Loading/Approach Path: \"nan\" is not a finite number")
