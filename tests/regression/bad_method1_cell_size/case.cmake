# Bad input stops with exit code 2 before any solving, with a message naming the problem.
# Method 1 on the default deck at gammaL = 200: the cells at the surfaces are 5 r0 long, and in
# contact no Gauss order the kernel holds integrates their pairs to the Volume Quadrature
# Tolerance; the message names the tolerance and the cell size needed (1.68 r0) and how to get it.
cgcm_bad_input(SANITIZE REGEX "up to 5 r0 long.*Volume Quadrature Tolerance = 0.0001. Cells of at most 1.68 r0 there meet it.*Geometry/Contact Zone Size")
