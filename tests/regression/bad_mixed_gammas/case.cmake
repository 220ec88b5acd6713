# Bad decks stop before any work with a message naming the parameter (cgcm_bad_deck: the
# output must match; the exit code is not checked). Here: gammaL bar given with gammaL
# (one pair is given, not two).
cgcm_bad_deck(SANITIZE REGEX "give one of")
