# Runs ONE unit test (tests/unit/NAME.cc); invoked by ctest as
#   cmake -DTEST_NAME=... -DNPROC=... -DEXECUTABLE=... -DEXPECTED=...
#         -DRUN_DIR=... -DNUMDIFF=... -DMPIEXEC=... [-DNUMDIFF_FILE=...]
#         -P run_unit_test.cmake
# The executable runs in a fresh RUN_DIR; its stdout (rank 0 writes it) is
# compared with EXPECTED by numdiff. See tests/README.md, "Unit tests".

cmake_minimum_required(VERSION 3.13)

foreach(_var TEST_NAME NPROC EXECUTABLE EXPECTED RUN_DIR NUMDIFF)
  if(NOT DEFINED ${_var} OR "${${_var}}" STREQUAL "")
    message(FATAL_ERROR "run_unit_test.cmake: variable ${_var} is not set")
  endif()
endforeach()

include("${CMAKE_CURRENT_LIST_DIR}/test_common.cmake")

if(NOT EXISTS "${EXPECTED}")
  _fail("expected output ${EXPECTED} does not exist")
endif()
if(NOT EXISTS "${EXECUTABLE}")
  _fail("executable ${EXECUTABLE} does not exist (build first)")
endif()

file(REMOVE_RECURSE "${RUN_DIR}")
file(MAKE_DIRECTORY "${RUN_DIR}")
set(_output "${RUN_DIR}/test-output")
set(_stderr "${RUN_DIR}/stderr")

_mpi_launcher(_launcher)

execute_process(
  COMMAND ${_launcher} "${EXECUTABLE}"
  WORKING_DIRECTORY "${RUN_DIR}"
  OUTPUT_FILE "${_output}"
  ERROR_FILE "${_stderr}"
  RESULT_VARIABLE _rc)
if(NOT _rc STREQUAL "0")
  file(READ "${_output}" _out)
  file(READ "${_stderr}" _err)
  message("---- stdout:\n${_out}\n---- stderr:\n${_err}")
  _fail("the executable exited with status '${_rc}'")
endif()

# Numdiff options: first line of tests/unit/NAME.numdiff, else the defaults
# of the scene tests.
set(_numdiff_opts -a 1e-10 -r 1e-6)
if(NUMDIFF_FILE AND EXISTS "${NUMDIFF_FILE}")
  file(STRINGS "${NUMDIFF_FILE}" _lines LIMIT_COUNT 1)
  if(_lines)
    list(GET _lines 0 _line)
    separate_arguments(_numdiff_opts UNIX_COMMAND "${_line}")
  endif()
endif()
list(APPEND _numdiff_opts -s " \t\n,:=")

execute_process(
  COMMAND "${NUMDIFF}" -q ${_numdiff_opts} "${_output}" "${EXPECTED}"
  RESULT_VARIABLE _nd_rc
  OUTPUT_QUIET ERROR_QUIET)
if(NOT _nd_rc STREQUAL "0")
  execute_process(
    COMMAND "${NUMDIFF}" ${_numdiff_opts} "${_output}" "${EXPECTED}"
    OUTPUT_VARIABLE _nd_out
    ERROR_VARIABLE _nd_out)
  string(JOIN " " _opts_str ${_numdiff_opts})
  message("---- numdiff ${_opts_str} ${_output} ${EXPECTED}\n${_nd_out}")
  _fail("output differs from ${EXPECTED} (numdiff status '${_nd_rc}')")
endif()

message("TEST ${TEST_NAME} PASSED")
