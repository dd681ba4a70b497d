# cmake -DBUILD_DIR=... -DPREFIX=... -P InstallPrefix.cmake
# Installs the build tree into an emptied PREFIX and checks the package's files are there.
foreach (var IN ITEMS BUILD_DIR PREFIX)
  if (NOT DEFINED ${var})
    message(FATAL_ERROR "InstallPrefix.cmake: -D${var}=... is required")
  endif ()
endforeach ()
file(REMOVE_RECURSE "${PREFIX}")
execute_process(
  COMMAND "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${PREFIX}"
  RESULT_VARIABLE result
  OUTPUT_VARIABLE output
  ERROR_VARIABLE output)
if (NOT result EQUAL 0)
  message(FATAL_ERROR "cmake --install failed (${result}):\n${output}")
endif ()
file(GLOB_RECURSE config LIST_DIRECTORIES false "${PREFIX}/*/RefractionConfig.cmake")
if (NOT config)
  message(FATAL_ERROR "no RefractionConfig.cmake under ${PREFIX}:\n${output}")
endif ()
message(STATUS "installed into ${PREFIX}: ${config}")
