# cmake -DSOURCE_DIR=... -DBINARY_DIR=... -DPREFIX=... [-DCONFIGURE_ONLY=ON] [-DCONFIGURE_ARGS=a;b]
#       [-DPROGRAM=name -DPROGRAM_ARGS=a;b;...] -P RunConsumer.cmake
# Configures a consumer project against the installed PREFIX from an empty build folder,
# builds it and runs its program: each step fails the test with the step's output.
foreach (var IN ITEMS SOURCE_DIR BINARY_DIR PREFIX)
  if (NOT DEFINED ${var})
    message(FATAL_ERROR "RunConsumer.cmake: -D${var}=... is required")
  endif ()
endforeach ()

function (run_step name)
  execute_process(COMMAND ${ARGN}
    RESULT_VARIABLE result
    OUTPUT_VARIABLE output
    ERROR_VARIABLE output)
  message(STATUS "${name}:\n${output}")
  if (NOT result EQUAL 0)
    message(FATAL_ERROR "${name} failed (${result})")
  endif ()
endfunction ()

file(REMOVE_RECURSE "${BINARY_DIR}")
set(configure_args -S "${SOURCE_DIR}" -B "${BINARY_DIR}" -DCMAKE_BUILD_TYPE=Release
  "-DCMAKE_PREFIX_PATH=${PREFIX}" "-DEXPECTED_PREFIX=${PREFIX}")
list(APPEND configure_args ${CONFIGURE_ARGS})
if (DEFINED GENERATOR)
  list(APPEND configure_args -G "${GENERATOR}")
endif ()
run_step("configure" "${CMAKE_COMMAND}" ${configure_args})
if (CONFIGURE_ONLY)
  return ()
endif ()
run_step("build" "${CMAKE_COMMAND}" --build "${BINARY_DIR}")
if (DEFINED PROGRAM)
  run_step("${PROGRAM}" "${BINARY_DIR}/${PROGRAM}" ${PROGRAM_ARGS})
endif ()
