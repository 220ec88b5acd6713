# Method 3 on curved 3D facets across ranks (deck.xml: ../../regression/3d_sphere_hex_quadratic's
# HEX27 quarter model, approach to u = -0.012, MUMPS on both rank counts): each rank's points on its
# own QUAD9 facets, projected onto every body's curved facets; np = 1 and np = 2 give the same curve
# (1e-7) and the same results.e.
cgcm_ranks_agree()
