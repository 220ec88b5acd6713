# Bad input stops with exit code 2 before any solving, with a message naming the problem.
# Method 1 needs the whole bodies: a symmetric part of them is refused. Here: the quarter
# model of inputs/3d/sphere-on-half-space.xml.
cgcm_bad_input(SANITIZE REGEX "symmetric part of them .\"symmetry x\", \"symmetry y\"")
