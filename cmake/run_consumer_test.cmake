# The consumer test (CTest: consumer_find_package), run with cmake -P:
# installs this build into a private prefix, then configures, builds and runs
# test/consumer, a separate project that finds diffuv with find_package()
# through that prefix only, and runs the installed tool once. Any failing step
# fails the test.
#
# -D variables (set by add_test in the top-level CMakeLists.txt):
#   DIFFUV_BUILD_DIR    the diffuv build tree to install
#   CONSUMER_SOURCE_DIR test/consumer
#   INSTALL_PREFIX      where to install (emptied first)
#   CONSUMER_BUILD_DIR  the consumer's build tree (emptied first)
#   CXX_COMPILER        the C++ compiler diffuv was configured with
#   GENERATOR           the CMake generator diffuv was configured with
#   CONFIG              the configuration to install (and, with a multi-config
#                       generator, to build); may be empty. With a single-config
#                       generator the consumer keeps its default (empty) build
#                       type: unoptimized, the quickest to compile.
#   COMPILER_LAUNCHER   e.g. ccache (may be empty)
#   EXAMPLE_SOURCE      optional: an example of examples/, copied into the
#                       consumer's build tree and built there as diffuv_example
#   EXAMPLE_MESH        with EXAMPLE_SOURCE: the mesh file to run it on; it is
#                       also run without one in an empty folder, where it must
#                       fail with its usage message
cmake_minimum_required(VERSION 3.16)

foreach(var DIFFUV_BUILD_DIR CONSUMER_SOURCE_DIR INSTALL_PREFIX CONSUMER_BUILD_DIR CXX_COMPILER GENERATOR)
  if(NOT DEFINED ${var} OR "${${var}}" STREQUAL "")
    message(FATAL_ERROR "run_consumer_test.cmake: -D${var}=... is required")
  endif()
endforeach()

function(run_step name)
  string(TIMESTAMP start "%s")
  message(STATUS "[consumer] ${name}: ${ARGN}")
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc)
  string(TIMESTAMP stop "%s")
  math(EXPR seconds "${stop} - ${start}")
  if(NOT rc STREQUAL "0")
    message(FATAL_ERROR "[consumer] ${name} failed (${rc}) after ${seconds} s")
  endif()
  message(STATUS "[consumer] ${name}: ok (${seconds} s)")
endfunction()

set(config_args)
if(CONFIG)
  set(config_args --config "${CONFIG}")
endif()

# 1. Install into a fresh prefix, so that no file of an earlier run survives.
file(REMOVE_RECURSE "${INSTALL_PREFIX}" "${CONSUMER_BUILD_DIR}")
run_step(install "${CMAKE_COMMAND}" --install "${DIFFUV_BUILD_DIR}" --prefix "${INSTALL_PREFIX}" ${config_args})
file(GLOB_RECURSE config_files "${INSTALL_PREFIX}/*/diffuvConfig.cmake")
if(NOT config_files)
  message(FATAL_ERROR "[consumer] the install put no diffuvConfig.cmake under ${INSTALL_PREFIX}")
endif()

# 2. Configure the consumer against that prefix only: no package registry, and
#    the consumer checks that diffuv and its include directories come from
#    INSTALL_PREFIX (see test/consumer/CMakeLists.txt).
set(configure_args
  -S "${CONSUMER_SOURCE_DIR}" -B "${CONSUMER_BUILD_DIR}" -G "${GENERATOR}"
  "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}"
  "-DCMAKE_PREFIX_PATH=${INSTALL_PREFIX}"
  "-DDIFFUV_EXPECTED_PREFIX=${INSTALL_PREFIX}"
  -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF
  -DCMAKE_FIND_USE_SYSTEM_PACKAGE_REGISTRY=OFF)
if(COMPILER_LAUNCHER)
  list(APPEND configure_args "-DCMAKE_CXX_COMPILER_LAUNCHER=${COMPILER_LAUNCHER}")
endif()
if(EXAMPLE_SOURCE)
  get_filename_component(example_name "${EXAMPLE_SOURCE}" NAME)
  set(example_copy "${CONSUMER_BUILD_DIR}/copied-example/${example_name}")
  file(COPY "${EXAMPLE_SOURCE}" DESTINATION "${CONSUMER_BUILD_DIR}/copied-example")
  list(APPEND configure_args "-DDIFFUV_EXAMPLE_SOURCE=${example_copy}")
endif()
run_step(configure "${CMAKE_COMMAND}" ${configure_args})

# 3. Build it.
run_step(build "${CMAKE_COMMAND}" --build "${CONSUMER_BUILD_DIR}" ${config_args})

# 4. Run it.
set(program "${CONSUMER_BUILD_DIR}/diffuv_consumer")
if(NOT EXISTS "${program}" AND CONFIG AND EXISTS "${CONSUMER_BUILD_DIR}/${CONFIG}/diffuv_consumer")
  set(program "${CONSUMER_BUILD_DIR}/${CONFIG}/diffuv_consumer")
endif()
run_step(run "${program}")

# 5. The copied example: on the mesh given, and without one in an empty
#    folder, where it must say how to call it rather than crash or succeed.
if(EXAMPLE_SOURCE)
  set(example "${CONSUMER_BUILD_DIR}/diffuv_example")
  if(NOT EXISTS "${example}" AND CONFIG AND EXISTS "${CONSUMER_BUILD_DIR}/${CONFIG}/diffuv_example")
    set(example "${CONSUMER_BUILD_DIR}/${CONFIG}/diffuv_example")
  endif()
  set(empty "${CONSUMER_BUILD_DIR}/empty-folder")
  file(MAKE_DIRECTORY "${empty}")
  run_step(example "${example}" "${EXAMPLE_MESH}")
  execute_process(COMMAND "${example}" WORKING_DIRECTORY "${empty}" RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_QUIET)
  string(STRIP "${err}" err)
  if(rc STREQUAL "0" OR NOT err MATCHES "^Usage: ")
    message(FATAL_ERROR "[consumer] the example without a mesh, in an empty folder: exit ${rc}, stderr: ${err}")
  endif()
  message(STATUS "[consumer] example without a mesh: exit ${rc}, ${err}")
endif()

# 6. The installed tool, when it is built, finds its default mesh in the
#    prefix, not in the build tree: run from another folder, without
#    DIFFUV_DATA_DIR, it names the installed cow.off.
file(GLOB tool LIST_DIRECTORIES false "${INSTALL_PREFIX}/*/diffuv")
if(tool)
  set(work "${CONSUMER_BUILD_DIR}/tool-run")
  file(MAKE_DIRECTORY "${work}")
  message(STATUS "[consumer] installed tool: ${tool} segment")
  execute_process(COMMAND "${CMAKE_COMMAND}" -E env --unset=DIFFUV_DATA_DIR "${tool}" segment -o "${work}/out"
    WORKING_DIRECTORY "${work}" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc STREQUAL "0")
    message(FATAL_ERROR "[consumer] the installed tool failed (${rc}): ${err}")
  endif()
  string(FIND "${out}" "diffuv segment ${INSTALL_PREFIX}/" at)
  string(FIND "${out}" "/diffuv/meshes/cow.off:" mesh_at)
  if(NOT at EQUAL 0 OR mesh_at EQUAL -1)
    message(FATAL_ERROR "[consumer] the installed tool did not take its mesh from ${INSTALL_PREFIX}: ${out}")
  endif()
  message(STATUS "[consumer] installed tool: ok (its cow.off is the installed one)")
endif()
