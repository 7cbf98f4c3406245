#ifndef vefs_abort_guard_h
#define vefs_abort_guard_h

#include <string>
#include <vector>

namespace vefs
{
  /**
   * While alive, an abort inside p4est (sc_abort(): p4est's save stops the
   * process when a write fails, e.g. "first file tell" on a full disk)
   * prints @p message, removes @p paths (the partial checkpoint, the lock
   * of the output directory) and ends all ranks with status 1 through
   * MPI_Abort, instead of a SIGABRT with no word from vefs
   * (doc/checkpoints.md, "Full disks"). One guard at a time.
   */
  class AbortGuard
  {
  public:
    AbortGuard(const std::string              &message,
               const std::vector<std::string> &paths);
    ~AbortGuard();

    AbortGuard(const AbortGuard &) = delete;
    AbortGuard &
    operator=(const AbortGuard &) = delete;
  };
} // namespace vefs

#endif
