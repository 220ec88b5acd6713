# Bad input stops with exit code 2 before any solving, with a message naming the problem.
# Bodies/<name>/Rigid is true or false (deck.xml is a link to the default deck).
cgcm_bad_input(ARGS "Bodies/sphere/Rigid=yes" REGEX "Bodies/sphere/Rigid = \"yes\": allowed values are true, false")
