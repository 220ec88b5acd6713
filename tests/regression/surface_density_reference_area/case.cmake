# Method 3 with Interaction/Surface Density = reference area (beta0 over the
# undeformed area element, doc/theory.md#surface-density) on the default deck
# (deck.xml is a link to it): P_min and the contact-phase state at u = 0.046,
# 0.5 % as for the default (measured -5.6189e-4 and 6.5937e-3; the default,
# beta0 over the current area, gives -5.6355e-4 and 6.5326e-3).
cgcm_run(ARGS "Interaction/Surface Density=reference area" Output/Exodus=false)
cgcm_check(COMMAND ${check} pulloff ${run}/load_curve.csv --expected=-5.6189e-4 --tolerance 0.005)
cgcm_check(AS contact_state COMMAND ${check} value ${run}/load_curve.csv --u 0.046 --expected=6.5937e-3 --tolerance 0.005)
