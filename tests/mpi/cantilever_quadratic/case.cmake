# The thin strip of tests/regression/cantilever_bending on quadratic 3D cells
# (HEX27, TETRA10; deck.xml is a link to its deck) on two ranks: the cells
# and their mid-edge, face and centre nodes split over the ranks give the
# one-rank curve. Both runs stop Newton at |f| <= 1e-10 E t while the tip
# force is P ~ 2.5e-7 E t, so they may differ by up to 4e-4 of P; they
# differ by 5e-8.
foreach(cell hex27 tet10)
  if(cell STREQUAL "hex27")
    set(args Problem/Formulation=3D "Geometry/Block/Cells Y=1")
  else()
    set(args Problem/Formulation=3D "Geometry/Block/Cells Y=1" Geometry/Block/Element=tet4)
  endif()
  cgcm_run(AS np2_${cell} RANKS 2 ARGS ${args})
  cgcm_check(AS np1_vs_np2_${cell} FIXTURES regression_cantilever_bending_run_${cell} ${name}_np2_${cell}
             COMMAND ${compare_csv} ${outputs}/regression/regression_cantilever_bending_run_${cell}/load_curve.csv
                     ${run}_np2_${cell}/load_curve.csv --columns u,P --rel 4e-4 --abs 1e-12)
endforeach()
