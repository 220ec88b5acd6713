# Bad decks stop before any work with a message naming the parameter (cgcm_bad_deck: the
# output must match; the exit code is not checked). Here: an approach path that keeps
# moving the same way through a waypoint (a path lists only its turning points).
cgcm_bad_deck(SANITIZE REGEX "Approach Path")
