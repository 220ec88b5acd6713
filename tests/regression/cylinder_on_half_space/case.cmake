# The cylinder on the half-space in plane strain (deck.xml is a link to
# inputs/cylinder-on-half-space.xml): the load-control pull-off (the minimum
# over the retraction) against the Maugis-Dugdale cylinder of Baney & Hui at
# the deck's lambda, in F = (pi^2 w^2 E* R)^(1/3): elastic half-space
# (lambda = 0.3585, -0.5447 F = -1.9827e-3; measured -1.4 %), rigid flat
# (lambda = 0.2259, -0.4635 F = -2.1253e-3; measured -4.6 %). The tolerances
# are the law's, not the mesh's: at small lambda the cylinder's pull-off
# depends on the shape of the interaction law, and the Lennard-Jones 9-3 law
# holds 0.861 of Dugdale's at lambda -> 0 (doc/validation.md, "The cylinder";
# the cylinder map has -5.0 % at lambda = 0.2): 3 % and 7 %.
cgcm_run(AS elastic ARGS Output/Exodus=false)
cgcm_check(AS elastic_pulloff FIXTURES ${name}_elastic
           COMMAND ${check} pulloff ${run}_elastic/load_curve.csv --retraction --expected=-1.9827e-3 --tolerance 0.03)
cgcm_run(AS rigid_flat ARGS Bodies/half-space/Rigid=true Output/Exodus=false)
cgcm_check(AS rigid_flat_pulloff FIXTURES ${name}_rigid_flat
           COMMAND ${check} pulloff ${run}_rigid_flat/load_curve.csv --retraction --expected=-2.1253e-3 --tolerance 0.07)
