# Bad decks stop before any work with a message naming the parameter (cgcm_bad_deck: the
# output must match; the exit code is not checked). Here: a potential that is not one of
# the choices.
cgcm_bad_deck(SANITIZE REGEX "Potential")
