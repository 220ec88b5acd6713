# Bad input stops with exit code 2 before any solving, with a message naming the problem.
# Gmsh Options (and Mesh Numbers, Mesh Cache) mesh a .geo: with a built-in geometry they would be ignored.
cgcm_bad_input(SANITIZE DECK ../method1_half_model/deck-half.xml ARGS "Geometry/Gmsh Options/Mesh.Algorithm=6"
               REGEX "Geometry/Gmsh Options applies to Geometry/Type = .gmsh. only, not .sphere on half-space.")
