# Bad decks stop before any work with a message naming the parameter (cgcm_bad_deck: the
# output must match; the exit code is not checked). Here: a partition that is not one of
# the choices, in one line with the allowed ones.
cgcm_bad_deck(SANITIZE REGEX "Solver/Partition = \"metis\": not a choice. allowed: \"geometric\", \"contiguous\"")
