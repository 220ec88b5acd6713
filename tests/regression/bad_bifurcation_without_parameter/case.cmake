# Bad input stops with exit code 2 before any solving, with a message naming the problem.
# A fold is followed in a second parameter: Turning Point needs a Continuation Parameter other than u.
cgcm_bad_input(SANITIZE DECK ../fold_curve/deck.xml ARGS "Loading/Continuation Parameter=u" "Loading/Parameter Path={}"
               REGEX "LOCA/Bifurcation/Type = Turning Point follows the Approach Path's first fold in a second parameter")
