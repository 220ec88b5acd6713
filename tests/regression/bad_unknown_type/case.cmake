# Bad input stops with exit code 2 before any solving, with a message naming the problem.
# Found by fuzzing (tests/fuzz): messages that were Teuchos' own (source file, throw
# count, "ANONYMOUS->") are one line naming the parameter. Here: a parameter type Teuchos
# knows but a deck does not use.
cgcm_bad_input(SANITIZE
               REGEX "Interaction/gammaW: type \"long\" is not one a deck uses. allowed: double, int, bool, string")
