# Shared by run_test.cmake and run_unit_test.cmake: Open MPI allowed to run
# as root (CI and users may be root) and without the single-copy mechanism
# that containers refuse, and the one way a test reports its failure.

set(ENV{OMPI_ALLOW_RUN_AS_ROOT} 1)
set(ENV{OMPI_ALLOW_RUN_AS_ROOT_CONFIRM} 1)
if(NOT DEFINED ENV{OMPI_MCA_btl_vader_single_copy_mechanism})
  set(ENV{OMPI_MCA_btl_vader_single_copy_mechanism} none)
endif()

function(_fail)
  string(JOIN "" _msg ${ARGV})
  message(FATAL_ERROR "*** TEST ${TEST_NAME} FAILED: ${_msg}")
endfunction()
