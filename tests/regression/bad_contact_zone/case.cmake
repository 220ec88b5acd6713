# Bad decks stop before any work with a message naming the parameter (cgcm_bad_deck: the
# output must match; the exit code is not checked). Here: a contact zone size beyond its
# range (0.02 .. 0.85).
cgcm_bad_deck(SANITIZE REGEX "Contact Zone Size")
