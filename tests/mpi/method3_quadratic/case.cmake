# Method 3 on quadratic cells (QUAD9: each rank's points on its own curved segments, projected
# onto every body's curved segments; deck.xml: the default deck with Geometry/Element Order = 2,
# approach to u = -0.004, MUMPS on both rank counts): np = 1 and np = 2 give the same curve
# (1e-7) and the same results.e.
cgcm_ranks_agree()
