# Method 1 on quadratic cells (QUAD9: each rank's directed cell pairs of curved cells; deck.xml:
# tests/mpi/method1's deck with Geometry/Element Order = 2 and MUMPS: GMRES + Ifpack2 takes
# 500 s on these coupled curved cells, MUMPS a few): np = 1 and np = 2 give the same curve
# (1e-7) and the same results.e.
cgcm_ranks_agree()
