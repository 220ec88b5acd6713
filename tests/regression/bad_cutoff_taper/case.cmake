# Bad decks stop before any work with a message naming the parameter (cgcm_bad_deck: the
# output must match; the exit code is not checked). Here: a cutoff taper of 1, beyond its
# range (0 .. 0.9).
cgcm_bad_deck(SANITIZE REGEX "Cutoff Taper")
