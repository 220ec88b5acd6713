# Runs the app once (or twice with PRE_ARGS) and checks its exit code and
# output. Called by ctest as
#   cmake -DAPP=<exe> -DARGS=<a|b|c> [-DPRE_ARGS=<a|b>] -DEXPECT_EXIT=<n>
#         [-DEXPECT_STDOUT=<regex>] [-DEXPECT_STDERR=<regex>] [-DREJECT_STDOUT=<regex>] -P run_app_check.cmake
# Arguments are separated by '|' (a ';' would be split by the ctest command line).
foreach(var APP ARGS EXPECT_EXIT)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "run_app_check: ${var} is not set")
  endif()
endforeach()

if(DEFINED PRE_ARGS)
  string(REPLACE "|" ";" pre "${PRE_ARGS}")
  execute_process(COMMAND ${APP} ${pre} RESULT_VARIABLE pre_rc OUTPUT_VARIABLE pre_out ERROR_VARIABLE pre_err)
  if(NOT pre_rc EQUAL 0)
    message(FATAL_ERROR "preparatory run failed (exit ${pre_rc}): ${APP} ${pre}\n${pre_err}")
  endif()
endif()

string(REPLACE "|" ";" args "${ARGS}")
execute_process(COMMAND ${APP} ${args} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("exit code: ${rc}\nstdout:\n${out}\nstderr:\n${err}")
if(NOT rc STREQUAL "${EXPECT_EXIT}")
  message(FATAL_ERROR "expected exit code ${EXPECT_EXIT}, got ${rc}")
endif()
if(DEFINED EXPECT_STDOUT AND NOT out MATCHES "${EXPECT_STDOUT}")
  message(FATAL_ERROR "stdout does not match: ${EXPECT_STDOUT}")
endif()
if(DEFINED REJECT_STDOUT AND out MATCHES "${REJECT_STDOUT}")
  message(FATAL_ERROR "stdout matches what it must not: ${REJECT_STDOUT}")
endif()
if(DEFINED EXPECT_STDERR AND NOT err MATCHES "${EXPECT_STDERR}")
  message(FATAL_ERROR "stderr does not match: ${EXPECT_STDERR}")
endif()
