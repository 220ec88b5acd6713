# Writes FILE with LEVELS nested <ParameterList> elements, then runs the app
# on it and checks its exit code and output (run_app_check.cmake: APP, ARGS,
# EXPECT_EXIT, EXPECT_STDERR, ...). Called by ctest as
#   cmake -DFILE=<path> -DLEVELS=<n> -DAPP=<exe> -DARGS=<a|b> -DEXPECT_EXIT=<n> [...] -P deep_xml_check.cmake
foreach(var FILE LEVELS)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "deep_xml_check: ${var} is not set")
  endif()
endforeach()
string(REPEAT "<ParameterList name=\"a\">" ${LEVELS} open)
string(REPEAT "</ParameterList>" ${LEVELS} close)
file(WRITE ${FILE} "${open}${close}\n")
include(${CMAKE_CURRENT_LIST_DIR}/../analytic/run_app_check.cmake)
