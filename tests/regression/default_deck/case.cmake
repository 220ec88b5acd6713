# The default deck (the paper's gammaL = 50, gammaW = 200 benchmark; deck.xml
# is a link to inputs/sphere-on-half-space.xml: that deck, as it is): P_min
# and a contact-phase state (u = 0.046) against the reference values of
# doc/validation.md (0.5 %).
cgcm_run()
cgcm_check(COMMAND ${check} pulloff ${run}/load_curve.csv --expected=-5.6355e-4 --tolerance 0.005)
cgcm_check(AS contact_state COMMAND ${check} value ${run}/load_curve.csv --u 0.046 --expected=6.5326e-3 --tolerance 0.005)
