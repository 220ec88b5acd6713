# Bad decks stop before any work with a message naming the parameter (cgcm_bad_deck: the
# output must match; the exit code is not checked). Here: a LOCA parameter LOCA does not
# read (a typo) stops the run before any state is written.
cgcm_bad_deck(SANITIZE REGEX "LOCA/Stepper/Max Stepz")
