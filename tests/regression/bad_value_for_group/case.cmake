# Bad input stops with exit code 2 before any solving, with a message naming the problem.
# Found by fuzzing (tests/fuzz): messages that were Teuchos' own (source file, throw
# count, "ANONYMOUS->") are one line naming the parameter. Here: a value where a group of
# parameters belongs.
cgcm_bad_input(SANITIZE
               REGEX "Material: a group of parameters .<ParameterList name=\"Material\">. belongs here, not a value")
