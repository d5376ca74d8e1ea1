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
# Meshes whose default atlas still has a chart that is not one-to-one, with
# the reason measured (doc/layout.md); the sweep checks every other mesh for it.
set(diffuv_sweep_not_injective
  b9_mesh.off              # the layout leaves a non-disc: Voronoi patches instead, whose strips fold
  cheese.off               # the same, around its holes
  couplingdown.off         # CAD strips: two fallback patches of 11 and 13 runs with no interior path between junctions, one flat triangle each that no hand-off takes (one-to-one before the cuts between junctions)
  elephant-with-holes.off  # as cheese: strips around its holes
  mech-holes-shark.off     # CAD strips around holes
  pig.stl                  # 17 parts; since bad patches of 100 faces may be split (2026-12-06), a 17-vertex fallback patch of 5 runs whose corners, chosen by its maps, leave one flat triangle
  polygon_mesh.off         # refused before the repair split its non-manifold vertices; a 10-face fallback patch of 7 runs keeps one flat triangle
)
foreach(mesh IN LISTS diffuv_sweep_meshes)
  get_filename_component(name "${mesh}" NAME)
  set(not_injective 0)
  if(name IN_LIST diffuv_sweep_not_injective)
    set(not_injective 1)
  endif()
  add_test(NAME "sweep.${name}"
           COMMAND ${CMAKE_COMMAND} -DTOOL=$<TARGET_FILE:diffuv_tool> "-DMESH=${mesh}"
                   "-DOUT=${CMAKE_CURRENT_BINARY_DIR}/sweep/${name}" -DLIMIT=${DIFFUV_SWEEP_LIMIT}
                   -DNOT_INJECTIVE=${not_injective} -P "${PROJECT_SOURCE_DIR}/cmake/sweep_mesh.cmake")
  set_tests_properties("sweep.${name}" PROPERTIES LABELS sweep TIMEOUT ${diffuv_sweep_timeout})
endforeach()
