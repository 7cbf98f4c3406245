#ifndef vefs_write_failure_h
#define vefs_write_failure_h

#include <mpi.h>

#include <cstdint>
#include <functional>
#include <ostream>
#include <string>

namespace vefs
{
  /**
   * Why a write failed, from the error number it left (errno): "no space
   * left on the device" for ENOSPC, the system's text otherwise.
   */
  std::string
  write_failure_cause(const int error_number);

  /**
   * "cannot write 'PATH': CAUSE" for a write to @p path that just failed
   * (the cause from errno as the failure left it).
   */
  std::string
  write_failure(const std::string &path);

  /**
   * Write the file @p path with @p write and close it, checking every step
   * (the open, the writes, the flush at the close); what went wrong, or "".
   */
  std::string
  checked_write(const std::string                         &path,
                const std::function<void(std::ostream &)> &write);

  /**
   * Collective: if any rank has a @p problem (non-empty), throw
   * OutputError on every rank with the first rank's problem and
   * @p where (e.g. "after step 12 (t = 0.1)") appended; the run then stops
   * on all ranks alike (doc/checkpoints.md, "Full disks").
   */
  void
  throw_if_write_failed(const std::string &problem,
                        const std::string &where,
                        const MPI_Comm     comm);

  /**
   * Bytes free for this user on the file system that holds @p path, or
   * the largest value if it cannot be told.
   */
  std::uintmax_t
  free_bytes(const std::string &path);
} // namespace vefs

#endif
