# Solver/Linear Solver/Type = Stratimikos hands its sublist to Stratimikos as
# it is, from the deck or the command line (a deck with this sublist used to be
# refused: the flag that exempts it from validation was lost in a copy): KLU2
# through Stratimikos with one of Amesos2's own options gives the default
# deck's P_min (0.5 %).
cgcm_run()
cgcm_check(COMMAND ${check} pulloff ${run}/load_curve.csv --expected=-5.6355e-4 --tolerance 0.005)
