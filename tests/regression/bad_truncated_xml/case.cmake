# Bad input stops with exit code 2 before any solving, with a message naming the problem.
# Found by fuzzing (tests/fuzz): messages that were Teuchos' own (source file, throw
# count, "ANONYMOUS->") are one line naming the parameter. Here: the file ends inside an
# element. The deck keeps its name, truncated.xml, which the message names.
cgcm_bad_input(SANITIZE DECK truncated.xml REGEX "truncated.xml\" is not valid XML: XML parse error at line 5")
