# Bad input stops with exit code 2 before any solving, with a message naming the problem.
# A mesh with an inverted cell. The mesh is written by hand (inverted.msh.in, no gmsh can
# make it; *.msh files are ignored by git): the build tree gets inverted.msh, which the
# test names on the command line. By hand: cp inverted.msh.in inverted.msh, then cgcm
# deck.xml.
configure_file(${case_dir}/inverted.msh.in ${CMAKE_CURRENT_BINARY_DIR}/${case}/inverted.msh COPYONLY)
cgcm_bad_input(SANITIZE ARGS Geometry/File=${CMAKE_CURRENT_BINARY_DIR}/${case}/inverted.msh
               REGEX "inverted.msh.*element 1 .* is inverted")
