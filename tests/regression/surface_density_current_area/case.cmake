# The paper's form of Method 3, eq. (21), kept selectable: the default deck with
# Interaction/Surface Density = current area (beta0 over the current area
# element, doc/theory.md#surface-density; deck.xml is a link to the default
# deck). Its P_min and contact-phase state are those the default deck gave
# before the reference area became the default (-5.6355e-4; 6.5326e-3 at
# u = 0.046), 0.5 % as there; the default gives -5.6189e-4 and 6.5937e-3.
cgcm_run(ARGS "Interaction/Surface Density=current area" Output/Exodus=false)
cgcm_check(COMMAND ${check} pulloff ${run}/load_curve.csv --expected=-5.6355e-4 --tolerance 0.005)
cgcm_check(AS contact_state COMMAND ${check} value ${run}/load_curve.csv --u 0.046 --expected=6.5326e-3 --tolerance 0.005)
