# Runs PROGRAM with ARGS (separated by spaces) and fails unless it exits with EXPECTED_EXIT and its
# output (stdout and stderr together) matches EXPECTED_OUTPUT:
#   cmake -DPROGRAM=... -DARGS=... -DEXPECTED_EXIT=2 -DEXPECTED_OUTPUT=regex -P ExpectExit.cmake
separate_arguments(arguments UNIX_COMMAND "${ARGS}")
execute_process(COMMAND "${PROGRAM}" ${arguments}
  RESULT_VARIABLE exit_code
  OUTPUT_VARIABLE output
  ERROR_VARIABLE output)
if (NOT exit_code STREQUAL "${EXPECTED_EXIT}")
  message(FATAL_ERROR "${PROGRAM} ${ARGS}: exit ${exit_code}, expected ${EXPECTED_EXIT}\n${output}")
endif ()
if (NOT output MATCHES "${EXPECTED_OUTPUT}")
  message(FATAL_ERROR "${PROGRAM} ${ARGS}: output does not match '${EXPECTED_OUTPUT}'\n${output}")
endif ()
message(STATUS "exit ${exit_code}, output matches '${EXPECTED_OUTPUT}'")
