# Bad input stops with exit code 2 before any solving, with a message naming the problem.
# A surface density that is not one of the two (deck.xml is a link to the default deck).
cgcm_bad_input(ARGS "Interaction/Surface Density=current"
               REGEX "Interaction/Surface Density = \"current\": not a choice. allowed: \"current area\", \"reference area\"")
