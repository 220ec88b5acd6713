# Bad decks stop before any work with a message naming the parameter (cgcm_bad_deck: the
# output must match; the exit code is not checked). Here: parameter bounds with lower >
# upper.
cgcm_bad_deck(SANITIZE REGEX "Parameter Bounds")
