# --check: every check and the problem's set-up, its size and memory, nothing
# solved or written (deck.xml is a link to the default deck: its size).
cgcm_app_check(ARGS --check ${case_dir}/deck.xml Output/Directory=${run} EXIT 0
               STDOUT "valid. 1338 nodes, 1240 cells, 2676 unknowns, about [0-9]+ MB")
