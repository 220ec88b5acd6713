# Bad decks stop before any work with a message naming the parameter (cgcm_bad_deck: the
# output must match; the exit code is not checked). Here: Poisson's ratio 0.5
# (incompressible, out of range).
cgcm_bad_deck(SANITIZE REGEX "Poisson's Ratio")
