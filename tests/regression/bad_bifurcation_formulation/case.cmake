# Bad input stops with exit code 2 before any solving, with a message naming the problem.
# The minimally augmented formulation needs transposed solves, which cgcm's linear solvers do not offer.
cgcm_bad_input(SANITIZE DECK ../fold_curve/deck.xml ARGS "LOCA/Bifurcation/Formulation=Minimally Augmented"
               REGEX "LOCA/Bifurcation/Formulation: allowed values Moore-Spence")
