# Bad input stops with exit code 2 before any solving, with a message naming the problem.
# A Gmsh Options entry that is not a number option of gmsh (misspelt).
cgcm_bad_input(SANITIZE DECK ../bad_mesh_numbers/deck.xml ARGS "Geometry/Gmsh Options/Mesh.Algoritm=6"
               REGEX "Geometry/Gmsh Options/Mesh.Algoritm: not a number option of gmsh")
