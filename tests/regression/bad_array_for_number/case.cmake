# Bad input stops with exit code 2 before any solving, with a message naming the problem.
# Found by fuzzing (tests/fuzz): messages that were Teuchos' own (source file, throw
# count, "ANONYMOUS->") are one line naming the parameter. Here: an array where a number
# belongs.
cgcm_bad_input(SANITIZE REGEX "Interaction/gammaL: given as Array.double., expected double")
