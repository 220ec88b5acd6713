# Geometry/Mesh Cache: a run keeps its meshed .geo (meshes/sphere-on-half-space.geo
# at level 1) in a folder, the next run with the same key reads it (summary.txt:
# "mesh read from") and follows the same curve bit for bit; a run with another
# Mesh Numbers value meshes again (another key). The cache folder is emptied first.
set(cache ${out}/${name}_cache)
set(args "Geometry/Mesh Cache=${cache}" "Geometry/Mesh Numbers/level=1" "Loading/Approach Path={-0.02, 0.0}")
cgcm_test(AS clear COMMAND ${CMAKE_COMMAND} -E remove_directory ${cache})
set_tests_properties(${name}_clear PROPERTIES FIXTURES_SETUP ${name}_clear)
cgcm_run(AS first DECK ../gmsh_sphere_on_half_space/deck.xml ARGS ${args})
cgcm_run(AS second DECK ../gmsh_sphere_on_half_space/deck.xml ARGS ${args})
cgcm_run(AS other DECK ../gmsh_sphere_on_half_space/deck.xml ARGS ${args} "Geometry/Mesh Numbers/zone=0.4")
set_tests_properties(${name}_first PROPERTIES FIXTURES_REQUIRED ${name}_clear)
set_tests_properties(${name}_second ${name}_other PROPERTIES FIXTURES_REQUIRED ${name}_first)
cgcm_check(AS first_meshed FIXTURES ${name}_first COMMAND grep -q "meshed by gmsh in .* s, kept in ${cache}/" ${run}_first/summary.txt)
cgcm_check(AS second_read FIXTURES ${name}_second COMMAND grep -q "mesh read from ${cache}/" ${run}_second/summary.txt)
cgcm_check(AS other_meshed FIXTURES ${name}_other COMMAND grep -q "meshed by gmsh in" ${run}_other/summary.txt)
cgcm_check(AS same_curve FIXTURES ${name}_first ${name}_second
           COMMAND ${compare_csv} ${run}_first/load_curve.csv ${run}_second/load_curve.csv --columns u,P,gap --rel 0 --abs 0)
