# Bad input stops with exit code 2 before any solving, with a message naming the problem.
# Here: an odd Geometry/Azimuthal Cells; the built-in 3D quarter model's butterfly core has
# half of them on each of its two outer sides.
cgcm_bad_input(SANITIZE REGEX "Geometry/Azimuthal Cells = 7 is odd")
