# The 3D sphere on half-space (tests/regression/3d_sphere: one body over a
# substrate, tetrahedra, geometric partition, each rank searching from its own
# facets; deck.xml is a link to its deck) on two and three ranks (three:
# rank 0 cuts and sends two parts, one after the other; oversubscribed on two
# cores): the one-rank curve to solver tolerance (1e-7), and the same
# results.e, the interaction traction included (each rank's pairs summed on rank 0);
# each rank holds its own facets and ghosts of the others (summary.txt: the own
# facets add up to the whole surfaces, no rank holds more than all of them).
foreach(ranks 2 3)
  cgcm_run(AS np${ranks} RANKS ${ranks})
  cgcm_check(AS np1_vs_np${ranks} FIXTURES regression_3d_sphere ${name}_np${ranks}
             COMMAND ${compare_csv} ${outputs}/regression/regression_3d_sphere/load_curve.csv
                     ${run}_np${ranks}/load_curve.csv --columns u,P,gap,contact_radius,P_lower --rel 1e-7 --abs 1e-12)
  cgcm_check(AS results_np1_vs_np${ranks} FIXTURES regression_3d_sphere ${name}_np${ranks}
             COMMAND exo_compare --rel 1e-7 --abs 1e-10 ${outputs}/regression/regression_3d_sphere/results.e
                     ${run}_np${ranks}/results.e)
  cgcm_check(AS held_np${ranks} FIXTURES ${name}_np${ranks}
             COMMAND ${check_held} ${run}_np${ranks}/summary.txt --ranks ${ranks})
endforeach()
