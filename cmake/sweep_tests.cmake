# The sweep over CGAL's data set (doc/robustness.md): one CTest test per mesh
# of ${DIFFUV_DATA_DIR}/meshes, `sweep.<mesh file>`, labelled `sweep`; each
# runs cmake/sweep_mesh.cmake (a result, or a clear error, within a time limit).
#   ctest --test-dir build -L sweep -j2      # the sweep only
#   ctest --test-dir build -LE sweep         # everything else
# Included from test/CMakeLists.txt; needs the diffuv tool.
if(NOT TARGET diffuv_tool)
  return()
endif()
set(DIFFUV_SWEEP_LIMIT 120 CACHE STRING "Seconds one mesh of the sweep may take before it counts as a hang")
file(GLOB diffuv_sweep_meshes LIST_DIRECTORIES false "${DIFFUV_DATA_DIR}/meshes/*")
list(SORT diffuv_sweep_meshes)
math(EXPR diffuv_sweep_timeout "${DIFFUV_SWEEP_LIMIT} + 60")
foreach(mesh IN LISTS diffuv_sweep_meshes)
  get_filename_component(name "${mesh}" NAME)
  add_test(NAME "sweep.${name}"
           COMMAND ${CMAKE_COMMAND} -DTOOL=$<TARGET_FILE:diffuv_tool> "-DMESH=${mesh}"
                   "-DOUT=${CMAKE_CURRENT_BINARY_DIR}/sweep/${name}" -DLIMIT=${DIFFUV_SWEEP_LIMIT}
                   -P "${PROJECT_SOURCE_DIR}/cmake/sweep_mesh.cmake")
  set_tests_properties("sweep.${name}" PROPERTIES LABELS sweep TIMEOUT ${diffuv_sweep_timeout})
endforeach()
