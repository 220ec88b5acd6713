# Method 1 on the three spheres (tetrahedra, four bodies): the interaction
# forces of all bodies sum to zero in every component to round-off, and the
# outer spheres' forces are mirror images (the tetrahedron rule is symmetric).
# A coarse quadrature and a 3 r0 cutoff keep it short: this checks the
# balance, not the accuracy.
cgcm_run()
cgcm_check(COMMAND ${check} bodies ${run}/body_forces.csv --mirror 1 3 --axis x --zero x y z --mirror-tolerance 1e-9
                   --zero-tolerance 1e-10 --balance-tolerance 1e-10)
