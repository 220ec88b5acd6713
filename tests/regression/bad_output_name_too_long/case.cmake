# Bad input stops with exit code 2 before any solving, with a message naming the problem.
# Here: an output folder name beyond NAME_MAX (300 characters, given on the command line;
# deck.xml is a link to the default deck): the file system's refusal, as bad input (was
# exit 1).
string(REPEAT "x" 300 long_name)
cgcm_bad_input(SANITIZE ARGS "Output/Directory=${out}/${long_name}"
               REGEX "Output/Directory = .*: cannot create it .File name too long")
