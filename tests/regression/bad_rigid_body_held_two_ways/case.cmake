# Bad input stops with exit code 2 before any solving, with a message naming the problem.
# A rigid body translates as a whole: the block of inputs/examples/block-compression.xml
# (deck.xml is a link to it) is held at zmin and driven at zmax, so it cannot be rigid.
cgcm_bad_input(SANITIZE ARGS "Bodies/block/Rigid=true"
               REGEX "Bodies/block/Rigid: a rigid body moves as a whole, but its node sets \"zmin\" and \"zmax\" prescribe different z-displacements")
