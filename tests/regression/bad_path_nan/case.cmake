# Bad decks stop before any work with a message naming the parameter (cgcm_bad_deck: the
# output must match; the exit code is not checked). Here: NaN in the approach path given
# on the command line (deck.xml is a link to the default deck; NaN in a deck:
# ../bad_nan_in_path).
cgcm_bad_deck(SANITIZE ARGS "Loading/Approach Path={-0.02,nan}" REGEX "Approach Path")
