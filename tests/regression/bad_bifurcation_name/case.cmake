# Bad input stops with exit code 2 before any solving, with a message naming the problem.
# A misspelt name in the LOCA/Bifurcation list (LOCA reads it only when a fold is followed, late in a run).
cgcm_bad_input(SANITIZE DECK ../fold_curve/deck.xml ARGS LOCA/Bifurcation/Formulaton=Moore-Spence
               REGEX "LOCA/Bifurcation/Formulaton: not a parameter of LOCA's turning-point continuation")
