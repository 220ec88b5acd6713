# Bad input stops with exit code 2 before any solving, with a message naming the problem.
# Method 1's pair list would not fit in the memory allowed: every pair of cells within the
# cutoff is listed, (cutoff / cell size)^3 per cell near the contact (here 10 r0 over cells of
# 1 r0 in the 3D quarter model: more than 6e6 pairs, 1.2 GB, against Output/Max Memory = 1000).
cgcm_bad_input(SANITIZE DECK ../method1_quarter_model/deck-quarter.xml
               ARGS Geometry/Mesh\ Numbers/lcContact=0.02 Interaction/Cutoff=10 Output/Max\ Memory=1000
               REGEX "Interaction/Method = .volume pair.: at the start more than .* directed cell pairs .* more than Output/Max Memory = 1000 MB")
