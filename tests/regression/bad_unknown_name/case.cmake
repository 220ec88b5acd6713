# Bad decks stop before any work with a message naming the parameter (cgcm_bad_deck: the
# output must match; the exit code is not checked). Here: a misspelt parameter name.
cgcm_bad_deck(SANITIZE REGEX "Sphere Radus")
