# gmsh geometry: meshes/sphere-on-half-space.geo is the built-in mesh node for
# node, so the default deck gives the built-in curve (P_min within 0.5 % of
# the reference, and every row to 1e-8 of the built-in run).
# This case runs nothing: it compares the runs of ../gmsh_sphere_on_half_space and ../default_deck.
cgcm_check(FIXTURES regression_gmsh_sphere_on_half_space regression_default_deck
           COMMAND ${compare_csv} ${out}/regression_gmsh_sphere_on_half_space/load_curve.csv
                   ${out}/regression_default_deck/load_curve.csv --columns u,P,gap,contact_radius,P_lower
                   --rel 1e-8 --abs 1e-12)
