# Bad decks stop before any work with a message naming the parameter (cgcm_bad_deck: the
# output must match; the exit code is not checked). Here: a MUMPS ordering that is not one
# of the choices, in one line with the allowed ones.
cgcm_bad_deck(SANITIZE
              REGEX "Solver/Linear Solver/MUMPS Ordering = \"METIS\": not a choice. allowed: \"auto\", \"AMD\", \"PORD\"")
