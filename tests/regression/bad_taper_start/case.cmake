# Bad decks stop before any work with a message naming the parameter (cgcm_bad_deck: the
# output must match; the exit code is not checked). Here: a cutoff taper that starts below
# 2 r0, in the range of the repulsion (Cutoff 3 r0, Cutoff Taper 0.5).
cgcm_bad_deck(SANITIZE REGEX "Cutoff Taper.*Interaction/Cutoff")
