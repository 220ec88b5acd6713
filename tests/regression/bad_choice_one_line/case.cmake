# Bad input stops with exit code 2 before any solving, with a message naming the problem.
# Not a choice, in one line with the allowed values.
cgcm_bad_input(SANITIZE
               REGEX "Interaction/Potential = \"Buckingham\": not a choice. allowed: \"Lennard-Jones\", \"repulsive\", \"Morse\"")
