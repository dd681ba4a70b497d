# cmake -DBUILD=<build folder> -DPREFIX=<empty folder> -P TestInstall.cmake
# Installs the plugin as the README says (the component "plugin") and fails unless exactly the
# plugin's library and its plugins XML were installed, in ParaView's plugin folder layout.
file(REMOVE_RECURSE "${PREFIX}")
execute_process(
  COMMAND "${CMAKE_COMMAND}" --install "${BUILD}" --prefix "${PREFIX}" --component plugin
  RESULT_VARIABLE result)
if (NOT result EQUAL 0)
  message(FATAL_ERROR "cmake --install failed: ${result}")
endif ()
file(GLOB_RECURSE installed RELATIVE "${PREFIX}" "${PREFIX}/*")
list(SORT installed)
set(expected
  "lib/paraview-5.11/plugins/RefractionGlass.plugins.xml"
  "lib/paraview-5.11/plugins/RefractionGlass/RefractionGlass.so")
if (NOT installed STREQUAL expected)
  message(FATAL_ERROR "installed: ${installed}\nexpected: ${expected}")
endif ()
message(STATUS "installed: ${installed}")
