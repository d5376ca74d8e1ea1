# One mesh of the sweep over CGAL's data set (doc/robustness.md), as a CTest
# test: runs `diffuv param MESH -o OUT` into a fresh folder and checks that
# it ends with either
#   - exit 0, every output file there and not empty, no NaN in the uv table,
#     nothing on stderr but `diffuv: warning:` lines, and every chart
#     one-to-one (the table's total ends `yes`) unless the input has zero-area
#     faces (flat in any map) or NOT_INJECTIVE is set (a known exception,
#     cmake/sweep_tests.cmake; a listed mesh that becomes one-to-one fails
#     too, so that the list only shrinks); or
#   - exit 1, stderr exactly one line `diffuv: error: MESH[:LINE]: REASON`,
#     and no output folder left behind.
# Anything else fails: a signal, a timeout, another exit code (4 is an internal
# error), an unclear message, files left behind, missing or NaN outputs.
#
#   cmake -DTOOL=path/to/diffuv -DMESH=mesh.off -DOUT=folder [-DLIMIT=seconds] -P sweep_mesh.cmake
foreach(var TOOL MESH OUT)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "sweep_mesh.cmake: -D${var}=... is missing")
  endif()
endforeach()
if(NOT DEFINED LIMIT)
  set(LIMIT 120)
endif()

file(REMOVE_RECURSE "${OUT}")
get_filename_component(parent "${OUT}" DIRECTORY)
file(MAKE_DIRECTORY "${parent}")
string(TIMESTAMP start "%s")
execute_process(COMMAND "${TOOL}" param "${MESH}" -o "${OUT}"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT ${LIMIT})
string(TIMESTAMP stop "%s")
math(EXPR seconds "${stop} - ${start}")
string(STRIP "${err}" err)
message("diffuv param ${MESH}: exit ${rc} after ${seconds} s\n${out}${err}")

function(fail why)
  message(FATAL_ERROR "sweep: ${MESH}: ${why}")
endfunction()

if(NOT rc MATCHES "^[0-9]+$")
  fail("crashed or hung: ${rc}") # a signal ("Segmentation fault", "Child aborted") or "Process terminated due to timeout"
endif()
foreach(pattern "terminate called" "Sanitizer" "runtime error:" "Assertion" "internal error" "CGAL ERROR")
  string(FIND "${err}" "${pattern}" at)
  if(at GREATER -1)
    fail("'${pattern}' on stderr")
  endif()
endforeach()

# stderr, line by line (an empty stderr is no line).
if(err STREQUAL "")
  set(lines "")
else()
  string(REPLACE ";" "\\;" err_list "${err}")
  string(REPLACE "\n" ";" lines "${err_list}")
endif()

get_filename_component(stem "${MESH}" NAME_WLE)
if(rc EQUAL 0)
  foreach(line IN LISTS lines)
    if(NOT line MATCHES "^diffuv: warning: ")
      fail("exit 0 with a stderr line that is not a warning: ${line}")
    endif()
  endforeach()
  foreach(ending .obj .mtl .checker.png .uv.csv .patches.txt .png)
    set(file "${OUT}/${stem}${ending}")
    if(NOT EXISTS "${file}")
      fail("exit 0 but ${stem}${ending} is missing")
    endif()
    file(SIZE "${file}" size)
    if(size EQUAL 0)
      fail("exit 0 but ${stem}${ending} is empty")
    endif()
  endforeach()
  string(REGEX MATCH "\ntotal [^\n]*" total "\n${out}")
  if(total STREQUAL "")
    fail("exit 0 but no 'total' line in the patch table")
  endif()
  string(FIND "${out}" "zero-area face" zero_area)
  if(total MATCHES " yes$")
    if(NOT_INJECTIVE)
      fail("every chart is one-to-one now: take this mesh off the NOT_INJECTIVE list in cmake/sweep_tests.cmake")
    endif()
  elseif(NOT NOT_INJECTIVE AND zero_area EQUAL -1)
    fail("a chart is not one-to-one (the table's total line ends 'no'; see its flipped/degen/overlaps columns)")
  endif()
  file(STRINGS "${OUT}/${stem}.uv.csv" nans REGEX "[Nn][Aa][Nn]|[Ii][Nn][Ff]")
  if(nans)
    list(GET nans 0 first)
    fail("NaN or infinity in ${stem}.uv.csv: ${first}")
  endif()
  file(REMOVE_RECURSE "${OUT}") # passed: the outputs are not kept
elseif(rc EQUAL 1)
  list(LENGTH lines count)
  if(NOT count EQUAL 1)
    fail("exit 1 with ${count} lines on stderr instead of one 'diffuv: error: ${MESH}: ...'")
  endif()
  set(prefix "diffuv: error: ${MESH}")
  string(FIND "${err}" "${prefix}" at)
  string(LENGTH "${prefix}" length)
  if(at EQUAL 0)
    string(SUBSTRING "${err}" ${length} -1 reason)
  endif()
  if(NOT at EQUAL 0 OR NOT reason MATCHES "^(:[0-9]+)?: [^ ]")
    fail("exit 1 without a clear 'diffuv: error: ${MESH}: <reason>' line: ${err}")
  endif()
  if(EXISTS "${OUT}")
    fail("exit 1 but the output folder ${OUT} was left behind")
  endif()
else()
  fail("exit ${rc} (1: bad input, 0: a result; anything else is wrong here)")
endif()
