# Shared by run_test.cmake and run_unit_test.cmake: Open MPI allowed to run
# as root (CI and users may be root) and without the single-copy mechanism
# that containers refuse, the one way a test reports its failure, and the
# MPI launcher.

set(ENV{OMPI_ALLOW_RUN_AS_ROOT} 1)
set(ENV{OMPI_ALLOW_RUN_AS_ROOT_CONFIRM} 1)
if(NOT DEFINED ENV{OMPI_MCA_btl_vader_single_copy_mechanism})
  set(ENV{OMPI_MCA_btl_vader_single_copy_mechanism} none)
endif()

function(_fail)
  string(JOIN "" _msg ${ARGV})
  message(FATAL_ERROR "*** TEST ${TEST_NAME} FAILED: ${_msg}")
endfunction()

# The command prefix that runs a test on NPROC ranks: empty for one rank,
# else mpirun with --oversubscribe (more ranks than cores on small machines).
function(_mpi_launcher _outvar)
  if(NPROC GREATER 1)
    if(NOT MPIEXEC)
      _fail("test needs ${NPROC} MPI ranks but mpirun was not found")
    endif()
    set(${_outvar} "${MPIEXEC}" -np ${NPROC} --oversubscribe PARENT_SCOPE)
  else()
    set(${_outvar} "" PARENT_SCOPE)
  endif()
endfunction()
