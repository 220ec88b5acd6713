# Test cases in folders (tests/regression, tests/mpi; tests/regression/README.md):
# <suite>/<case>/deck.xml, the input (build/bin/cgcm tests/<suite>/<case>/deck.xml
# runs it by hand), and <suite>/<case>/case.cmake, what is checked, with the
# expected values and the reasons for the tolerances, written with the
# functions below. cgcm_add_cases(<suite>) includes every <case>/case.cmake of
# the calling directory. The tests of a case are named <suite>_<case> and
# <suite>_<case>_<part>, labelled <suite>; its runs write to
# ${out}/<suite>_<case>[_<part>].
#
# Variables a case.cmake uses: case (the folder's name), case_dir (its path),
# name (<suite>_<case>), run (${out}/${name}, the output folder of cgcm_run),
# out (build/tests/output/<suite>), outputs (build/tests/output: another
# suite's runs), check (tests/tools/check_load_curve.py), compare_csv
# (tests/tools/compare_csv.py), check_held (tests/tools/check_held_surfaces.py:
# what each rank holds, from summary.txt), analytic (cgcm-analytic), quiet
# (Output/Print Steps=false), CGCM_MPIEXEC (the MPI launcher).
#
# SANITIZE (every function): the test is also in the CI-sized subset that runs
# in the sanitizer build (make sanitize: ctest -L "unit|sanitize" with
# AddressSanitizer + UndefinedBehaviorSanitizer): every kind of run once
# (built-in and gmsh meshes, 2D and 3D, both methods, a jump, a kill and a
# restart) and every bad input.

# <suite>_<case>, or <suite>_<case>_<part> with AS <part>.
macro(_cgcm_test_name var part)
  if("${part}" STREQUAL "")
    set(${var} ${name})
  else()
    set(${var} ${name}_${part})
  endif()
endmacro()

# A file of the case's folder (default deck.xml), or an absolute path.
macro(_cgcm_deck var file)
  if("${file}" STREQUAL "")
    set(${var} ${case_dir}/deck.xml)
  elseif(IS_ABSOLUTE "${file}")
    set(${var} ${file})
  else()
    set(${var} ${case_dir}/${file})
  endif()
endmacro()

function(_cgcm_labels test sanitize)
  if(sanitize)
    set_tests_properties(${test} PROPERTIES LABELS "${suite};sanitize")
  else()
    set_tests_properties(${test} PROPERTIES LABELS ${suite})
  endif()
endfunction()

# cgcm_run([AS <part>] [DECK <file>] [ARGS <overrides...>] [RANKS <n>] [PRINT_STEPS]
#          [EXIT <code> STDERR <regex>] [SANITIZE])
# cgcm on the case's deck with Output/Directory=${run}, Output/Print Steps=false
# (PRINT_STEPS: as the deck says) and ARGS: the test <suite>_<case>_run, which
# sets up the fixture <suite>_<case> for the checks (AS <part>: the test,
# fixture and output folder <suite>_<case>_<part>). RANKS: on n MPI ranks
# (${CGCM_MPIEXEC}), RUN_SERIAL. EXIT: the run must end with that exit code
# and its stderr match STDERR (tests/unit/analytic/run_app_check.cmake).
function(cgcm_run)
  cmake_parse_arguments(PARSE_ARGV 0 ARG "SANITIZE;PRINT_STEPS" "AS;DECK;RANKS;EXIT;STDERR" "ARGS")
  if(ARG_AS)
    set(test ${name}_${ARG_AS})
    set(fixture ${name}_${ARG_AS})
  else()
    set(test ${name}_run)
    set(fixture ${name})
  endif()
  _cgcm_deck(deck "${ARG_DECK}")
  set(args ${deck} Output/Directory=${out}/${fixture})
  if(NOT ARG_PRINT_STEPS)
    list(APPEND args ${quiet})
  endif()
  list(APPEND args ${ARG_ARGS})
  if(DEFINED ARG_EXIT)
    string(JOIN "|" args ${args})
    add_test(NAME ${test}
             COMMAND ${CMAKE_COMMAND} -DAPP=$<TARGET_FILE:cgcm> "-DARGS=${args}" -DEXPECT_EXIT=${ARG_EXIT}
                     "-DEXPECT_STDERR=${ARG_STDERR}" -P ${app_check})
  elseif(ARG_RANKS)
    add_test(NAME ${test} COMMAND ${CGCM_MPIEXEC} -np ${ARG_RANKS} $<TARGET_FILE:cgcm> ${args})
    set_tests_properties(${test} PROPERTIES RUN_SERIAL TRUE)
  else()
    add_test(NAME ${test} COMMAND cgcm ${args})
  endif()
  set_tests_properties(${test} PROPERTIES FIXTURES_SETUP ${fixture})
  _cgcm_labels(${test} "${ARG_SANITIZE}")
endfunction()

# cgcm_check([AS <part>] [FIXTURES <fixtures...>] [SANITIZE] COMMAND <command...>)
# A check of run outputs (check_load_curve.py, compare_csv.py, exo_compare):
# the test <suite>_<case>[_<part>], run after the case's cgcm_run (FIXTURES:
# after those runs instead, e.g. regression_jumps for the run of
# tests/regression/jumps).
function(cgcm_check)
  cmake_parse_arguments(PARSE_ARGV 0 ARG "SANITIZE" "AS" "FIXTURES;COMMAND")
  _cgcm_test_name(test "${ARG_AS}")
  if(NOT ARG_FIXTURES)
    set(ARG_FIXTURES ${name})
  endif()
  add_test(NAME ${test} COMMAND ${ARG_COMMAND})
  set_tests_properties(${test} PROPERTIES FIXTURES_REQUIRED "${ARG_FIXTURES}")
  _cgcm_labels(${test} "${ARG_SANITIZE}")
endfunction()

# cgcm_ranks_agree()
# The case's deck on one rank and on two (cgcm_run AS np1, AS np2 RANKS 2),
# and the checks <suite>_<case>_np1_vs_np2, the same load curve (u, P, gap,
# P_lower to 1e-7 relative, 1e-12 absolute), and
# <suite>_<case>_results_np1_vs_np2, the same results.e (exo_compare, 1e-7
# relative, 1e-10 absolute: the residuals, round-off, differ below it).
function(cgcm_ranks_agree)
  cgcm_run(AS np1)
  cgcm_run(AS np2 RANKS 2)
  cgcm_check(AS np1_vs_np2 FIXTURES ${name}_np1 ${name}_np2
             COMMAND ${compare_csv} ${run}_np1/load_curve.csv ${run}_np2/load_curve.csv --columns u,P,gap,P_lower
                     --rel 1e-7 --abs 1e-12)
  cgcm_check(AS results_np1_vs_np2 FIXTURES ${name}_np1 ${name}_np2
             COMMAND exo_compare --rel 1e-7 --abs 1e-10 ${run}_np1/results.e ${run}_np2/results.e)
endfunction()

# cgcm_bad_input([DECK <file>] [ARGS <overrides...>] [SANITIZE] REGEX <regex>)
# Bad input: cgcm on the deck (Output/Directory=${run}, then ARGS) stops with
# exit code 2 before any solving, its stderr matching "cgcm: error: .*<regex>".
function(cgcm_bad_input)
  cmake_parse_arguments(PARSE_ARGV 0 ARG "SANITIZE" "DECK;REGEX" "ARGS")
  _cgcm_deck(deck "${ARG_DECK}")
  string(JOIN "|" args ${deck} Output/Directory=${run} ${ARG_ARGS})
  add_test(NAME ${name}
           COMMAND ${CMAKE_COMMAND} -DAPP=$<TARGET_FILE:cgcm> "-DARGS=${args}" -DEXPECT_EXIT=2
                   "-DEXPECT_STDERR=cgcm: error: .*${ARG_REGEX}" -P ${app_check})
  _cgcm_labels(${name} "${ARG_SANITIZE}")
endfunction()

# cgcm_bad_deck([DECK <file>] [ARGS <overrides...>] [SANITIZE] REGEX <regex>)
# Bad input found by its message: the output of cgcm on the deck
# (Output/Directory=${run}, then ARGS) matches the regex; the exit code is not
# checked (cgcm_bad_input checks it).
function(cgcm_bad_deck)
  cmake_parse_arguments(PARSE_ARGV 0 ARG "SANITIZE" "DECK;REGEX" "ARGS")
  _cgcm_deck(deck "${ARG_DECK}")
  add_test(NAME ${name} COMMAND cgcm ${deck} Output/Directory=${run} ${ARG_ARGS})
  set_tests_properties(${name} PROPERTIES PASS_REGULAR_EXPRESSION "${ARG_REGEX}")
  _cgcm_labels(${name} "${ARG_SANITIZE}")
endfunction()

# cgcm_app_check([AS <part>] [PRE_ARGS <args...>] ARGS <args...> EXIT <code> [STDOUT <regex>]
#                [STDERR <regex>] [REJECT_STDOUT <regex>] [SANITIZE])
# cgcm with exactly these arguments (after a run with PRE_ARGS, which must
# succeed): its exit code and output (tests/unit/analytic/run_app_check.cmake).
function(cgcm_app_check)
  cmake_parse_arguments(PARSE_ARGV 0 ARG "SANITIZE" "AS;EXIT;STDOUT;STDERR;REJECT_STDOUT" "ARGS;PRE_ARGS")
  _cgcm_test_name(test "${ARG_AS}")
  string(JOIN "|" args ${ARG_ARGS})
  set(command ${CMAKE_COMMAND} -DAPP=$<TARGET_FILE:cgcm>)
  if(ARG_PRE_ARGS)
    string(JOIN "|" pre ${ARG_PRE_ARGS})
    list(APPEND command "-DPRE_ARGS=${pre}")
  endif()
  list(APPEND command "-DARGS=${args}" -DEXPECT_EXIT=${ARG_EXIT})
  foreach(stream STDOUT STDERR)
    if(DEFINED ARG_${stream})
      list(APPEND command "-DEXPECT_${stream}=${ARG_${stream}}")
    endif()
  endforeach()
  if(DEFINED ARG_REJECT_STDOUT)
    list(APPEND command "-DREJECT_STDOUT=${ARG_REJECT_STDOUT}")
  endif()
  add_test(NAME ${test} COMMAND ${command} -P ${app_check})
  _cgcm_labels(${test} "${ARG_SANITIZE}")
endfunction()

# cgcm_test([AS <part>] [PASS <regex>] [ENVIRONMENT <var=value...>] [SERIAL] [SANITIZE] COMMAND <command...>)
# Any other command (a script that kills and restarts cgcm, a benchmark, a
# test binary on several ranks): it must exit with 0, or (PASS) its output
# match the regex. SERIAL: RUN_SERIAL (MPI ranks).
function(cgcm_test)
  cmake_parse_arguments(PARSE_ARGV 0 ARG "SANITIZE;SERIAL" "AS;PASS" "ENVIRONMENT;COMMAND")
  _cgcm_test_name(test "${ARG_AS}")
  add_test(NAME ${test} COMMAND ${ARG_COMMAND})
  if(DEFINED ARG_PASS)
    set_tests_properties(${test} PROPERTIES PASS_REGULAR_EXPRESSION "${ARG_PASS}")
  endif()
  if(ARG_ENVIRONMENT)
    set_tests_properties(${test} PROPERTIES ENVIRONMENT "${ARG_ENVIRONMENT}")
  endif()
  if(ARG_SERIAL)
    set_tests_properties(${test} PROPERTIES RUN_SERIAL TRUE)
  endif()
  _cgcm_labels(${test} "${ARG_SANITIZE}")
endfunction()

# cgcm_add_cases(<suite>): every case of the calling directory, a folder with a
# case.cmake, named with lowercase letters, digits and _ (the parameter names
# gammaL and gammaW keep their capital).
function(cgcm_add_cases suite)
  set(outputs ${CMAKE_BINARY_DIR}/tests/output)
  set(out ${outputs}/${suite})
  set(check ${Python3_EXECUTABLE} ${CMAKE_SOURCE_DIR}/tests/tools/check_load_curve.py)
  set(compare_csv ${Python3_EXECUTABLE} ${CMAKE_SOURCE_DIR}/tests/tools/compare_csv.py)
  set(check_held ${Python3_EXECUTABLE} ${CMAKE_SOURCE_DIR}/tests/tools/check_held_surfaces.py)
  set(analytic $<TARGET_FILE:cgcm-analytic>)
  set(quiet "Output/Print Steps=false")
  set(app_check ${CMAKE_SOURCE_DIR}/tests/unit/analytic/run_app_check.cmake)
  file(GLOB case_files CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*/case.cmake)
  foreach(case_file ${case_files})
    get_filename_component(case_dir ${case_file} DIRECTORY)
    get_filename_component(case ${case_dir} NAME)
    if(NOT case MATCHES "^([a-z0-9_]|gammaL|gammaW)+$")
      message(FATAL_ERROR "${case_dir}: a case folder is named with a-z, 0-9 and _ (tests/regression/README.md)")
    endif()
    set(name ${suite}_${case})
    set(run ${out}/${name})
    include(${case_file})
  endforeach()
endfunction()
