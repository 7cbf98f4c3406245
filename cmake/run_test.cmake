# Runs ONE vefs test; invoked by ctest as
#   cmake -DTEST_NAME=... -DBASE_NAME=... -DNPROC=... -DVEFS=...
#         -DTEST_SOURCE_DIR=... -DRUN_DIR=... -DNUMDIFF=... -DMPIEXEC=...
#         -DPYTHON=... -DBASH=... -P run_test.cmake
# See tests/README.md for the conventions.

cmake_minimum_required(VERSION 3.13)

foreach(_var TEST_NAME BASE_NAME NPROC VEFS TEST_SOURCE_DIR RUN_DIR NUMDIFF)
  if(NOT DEFINED ${_var} OR "${${_var}}" STREQUAL "")
    message(FATAL_ERROR "run_test.cmake: variable ${_var} is not set")
  endif()
endforeach()
if(NOT PYTHON)
  set(PYTHON /usr/bin/python3)
endif()
if(NOT BASH)
  set(BASH bash)
endif()

include("${CMAKE_CURRENT_LIST_DIR}/test_common.cmake")

set(_src "${TEST_SOURCE_DIR}/${BASE_NAME}")
set(_expected "${TEST_SOURCE_DIR}/${TEST_NAME}.output")
set(_screen "${RUN_DIR}/screen-output")
set(_stderr "${RUN_DIR}/stderr")
set(_test_output "${RUN_DIR}/test-output")

# ---------------------------------------------------------------- helpers

# Print the last N lines of a file.
function(_print_tail _file _n _title)
  if(NOT EXISTS "${_file}")
    message("---- ${_title}: (no file ${_file})")
    return()
  endif()
  file(READ "${_file}" _text)
  string(REGEX REPLACE "\n$" "" _t "${_text}")
  set(_i 0)
  set(_pos -1)
  while(_i LESS _n)
    string(FIND "${_t}" "\n" _pos REVERSE)
    if(_pos EQUAL -1)
      break()
    endif()
    string(SUBSTRING "${_t}" 0 ${_pos} _t)
    math(EXPR _i "${_i} + 1")
  endwhile()
  if(_pos EQUAL -1)
    set(_tail "${_text}")
  else()
    math(EXPR _pos "${_pos} + 1")
    string(SUBSTRING "${_text}" ${_pos} -1 _tail)
  endif()
  message("---- ${_title} (last ${_n} lines of ${_file}):\n${_tail}")
endfunction()

# Remove Open MPI's own diagnostics from a text: blocks framed by lines of
# 74 dashes (help messages such as "Primary job terminated normally ...",
# "MPI_ABORT was invoked ...") and "[host:pid] ..." lines.
function(_strip_mpi_noise _in _outvar)
  set(_sep "--------------------------------------------------------------------------")
  string(LENGTH "${_sep}\n" _seplen)
  set(_text "\n${_in}")
  if(NOT _text MATCHES "\n$")
    string(APPEND _text "\n")
  endif()
  while(TRUE)
    string(FIND "${_text}" "\n${_sep}\n" _start)
    if(_start EQUAL -1)
      break()
    endif()
    math(EXPR _start "${_start} + 1")  # keep the preceding newline
    string(SUBSTRING "${_text}" 0 ${_start} _before)
    math(EXPR _after "${_start} + ${_seplen}")
    string(SUBSTRING "${_text}" ${_after} -1 _rest)
    string(FIND "${_rest}" "\n${_sep}\n" _end)
    if(_end EQUAL -1)
      # unterminated block: drop the rest
      set(_text "${_before}")
      break()
    endif()
    math(EXPR _end "${_end} + 1 + ${_seplen}")
    string(SUBSTRING "${_rest}" ${_end} -1 _rest)
    set(_text "${_before}${_rest}")
  endwhile()
  string(REGEX REPLACE "\n\\[[^\n:]*:[0-9]+\\][^\n]*" "" _text "${_text}")
  string(REGEX REPLACE "^\n" "" _text "${_text}")
  set(${_outvar} "${_text}" PARENT_SCOPE)
endfunction()

# ------------------------------------------------------------ preparation

if(NOT EXISTS "${_expected}")
  _fail("expected output ${_expected} does not exist")
endif()
if(NOT EXISTS "${VEFS}")
  _fail("executable ${VEFS} does not exist (build first)")
endif()

file(REMOVE_RECURSE "${RUN_DIR}")
file(MAKE_DIRECTORY "${RUN_DIR}")

if(EXISTS "${_src}.prm")
  file(COPY "${_src}.prm" DESTINATION "${RUN_DIR}")
endif()
# Optional auxiliary input files (meshes, ...): tests/NAME.inputs/*
if(IS_DIRECTORY "${_src}.inputs")
  file(GLOB _aux "${_src}.inputs/*")
  if(_aux)
    file(COPY ${_aux} DESTINATION "${RUN_DIR}")
  endif()
endif()

_mpi_launcher(_launcher)

# Numdiff options: first line of tests/NAME.numdiff, else defaults.
set(_numdiff_opts -q -a 1e-10 -r 1e-6)
if(EXISTS "${_src}.numdiff")
  file(STRINGS "${_src}.numdiff" _lines LIMIT_COUNT 1)
  if(_lines)
    list(GET _lines 0 _line)
    separate_arguments(_numdiff_opts UNIX_COMMAND "${_line}")
  endif()
endif()
# Commas separate fields too: otherwise numdiff reads "0.91," in
# "0.91, above 0.8" as text and compares it exactly, whatever the tolerance.
list(APPEND _numdiff_opts -s " \t\n,")
# A variant without -q, used to show the differences on failure.
set(_numdiff_verbose_opts ${_numdiff_opts})
list(REMOVE_ITEM _numdiff_verbose_opts -q --quiet)
set(_numdiff_quiet_opts ${_numdiff_verbose_opts} -q)

# -------------------------------------------------------------------- run

string(REGEX MATCH "^bad_" _is_bad "${BASE_NAME}")

if(EXISTS "${_src}.cmd")
  # Driver-script test: tests/NAME.cmd is run by bash in the run directory
  # with VEFS, MPIRUN (launcher prefix or empty), NPROC, TEST_SOURCE_DIR in
  # the environment. Its stdout is the test output; it must exit 0.
  set(ENV{VEFS} "${VEFS}")
  string(REPLACE ";" " " _launcher_str "${_launcher}")
  set(ENV{MPIRUN} "${_launcher_str}")
  set(ENV{NPROC} "${NPROC}")
  set(ENV{TEST_SOURCE_DIR} "${TEST_SOURCE_DIR}")
  execute_process(
    COMMAND "${BASH}" "${_src}.cmd"
    WORKING_DIRECTORY "${RUN_DIR}"
    OUTPUT_FILE "${_test_output}"
    ERROR_FILE "${_stderr}"
    RESULT_VARIABLE _rc)
  if(NOT _rc STREQUAL "0")
    _print_tail("${_test_output}" 30 "stdout")
    _print_tail("${_stderr}" 30 "stderr")
    _fail("${BASE_NAME}.cmd exited with status '${_rc}'")
  endif()
else()
  execute_process(
    COMMAND ${_launcher} "${VEFS}" "${BASE_NAME}.prm"
    WORKING_DIRECTORY "${RUN_DIR}"
    OUTPUT_FILE "${_screen}"
    ERROR_FILE "${_stderr}"
    RESULT_VARIABLE _rc)

  if(_is_bad)
    if(_rc STREQUAL "0")
      _print_tail("${_screen}" 30 "stdout")
      _print_tail("${_stderr}" 30 "stderr")
      _fail("bad-input test: vefs exited with status 0 but should fail")
    endif()
    file(READ "${_stderr}" _err)
    _strip_mpi_noise("${_err}" _err)
    file(WRITE "${_test_output}" "${_err}")
  else()
    if(NOT _rc STREQUAL "0")
      _print_tail("${_screen}" 30 "stdout")
      _print_tail("${_stderr}" 30 "stderr")
      _fail("vefs exited with status '${_rc}'")
    endif()
    if(NOT EXISTS "${_src}.py")
      _fail("no checker script tests/${BASE_NAME}.py: every numeric test "
            "needs one (it prints the quantities compared against "
            "tests/${TEST_NAME}.output)")
    endif()
    execute_process(
      COMMAND "${PYTHON}" "${_src}.py" "${RUN_DIR}/output"
      WORKING_DIRECTORY "${RUN_DIR}"
      OUTPUT_FILE "${_test_output}"
      ERROR_FILE "${RUN_DIR}/checker-stderr"
      RESULT_VARIABLE _prc)
    if(NOT _prc STREQUAL "0")
      _print_tail("${_test_output}" 30 "checker stdout")
      _print_tail("${RUN_DIR}/checker-stderr" 30 "checker stderr")
      _fail("checker ${BASE_NAME}.py exited with status '${_prc}'")
    endif()
  endif()
endif()

# ------------------------------------------------------------- comparison

execute_process(
  COMMAND "${NUMDIFF}" ${_numdiff_quiet_opts} "${_test_output}" "${_expected}"
  OUTPUT_VARIABLE _nd_out
  ERROR_VARIABLE _nd_out
  RESULT_VARIABLE _nd_rc)
if(NOT _nd_rc STREQUAL "0")
  execute_process(
    COMMAND "${NUMDIFF}" ${_numdiff_verbose_opts} "${_test_output}" "${_expected}"
    OUTPUT_VARIABLE _nd_out
    ERROR_VARIABLE _nd_out
    RESULT_VARIABLE _nd_rc2)
  string(JOIN " " _opts_str ${_numdiff_verbose_opts})
  message("---- numdiff ${_opts_str} ${_test_output} ${_expected}\n${_nd_out}")
  _fail("output differs from tests/${TEST_NAME}.output (numdiff status '${_nd_rc}')")
endif()

message("TEST ${TEST_NAME} PASSED")
