# Method 1 (volume pairs: each rank evaluates the directed cell pairs whose row
# cell it owns, the column cells' coordinates replicated; deck.xml: the default
# deck's approach to u = -0.004, the same iterative solver on both rank
# counts): np = 1 and np = 2 give the same curve on the approach (1e-7) and
# the same results.e, the interaction force on each node and the traction of
# the surface nodes included (each rank's pairs exported to the rows' owners,
# streamed to rank 0).
cgcm_ranks_agree()
