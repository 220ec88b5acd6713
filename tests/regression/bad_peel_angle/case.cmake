# Bad input stops with exit code 2 before any solving, with a message naming the problem.
# The peel mesh is drawn for peel angles 1 .. 170 degrees (at 180 the arm would lie on the
# strip); meshes/peel-strip.geo says so through gmsh.
cgcm_bad_input(DECK ../peel/deck.xml ARGS "Geometry/Mesh Numbers/theta=175"
               REGEX "peel-strip.geo\": gmsh: peel-strip.geo: needs 1 <= theta <= 170 degrees")
