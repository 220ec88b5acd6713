# Method 1 on a symmetric part in plane strain: the built-in half model (its
# "axis" is the symmetry line x = 0; the other half acts through image cells)
# and the whole model mirrored from the same mesh (meshes/sphere-on-half-space.geo)
# give the same curve, jump to contact included. Two systems solved to Newton's
# Residual Tolerance (1e-10) each: the half model's first state stops at
# |f| = 8e-11, the whole's at 2e-16, which moves P by 4e-10 (P is 4e-4 .. 2e-3
# here); hence P to 1e-9 absolute, u and gap to 1e-7.
cgcm_run(AS half DECK deck-half.xml)
cgcm_run(AS whole DECK deck-whole.xml)
cgcm_check(AS half_vs_whole FIXTURES ${name}_half ${name}_whole
           COMMAND ${compare_csv} ${run}_half/load_curve.csv ${run}_whole/load_curve.csv --columns u,P,gap --rel 1e-7 --abs 1e-9)
