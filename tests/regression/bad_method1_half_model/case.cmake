# Bad input stops with exit code 2 before any solving, with a message naming the problem.
# Method 1 needs the whole bodies: a symmetric part of them is refused. Here: the half
# model of plane strain.
cgcm_bad_input(SANITIZE REGEX "Method = .volume pair. integrates over the whole bodies")
