#include <mpi.h>
#include <sc.h>
#include <vefs/io/abort_guard.h>

#include <filesystem>
#include <iostream>

namespace vefs
{
  namespace
  {
    // sc's handler takes no argument: what it needs waits here.
    std::string              abort_message;
    std::vector<std::string> abort_paths;
    bool                     guard_alive = false;

    void
    end_run_on_abort()
    {
      std::cerr << "vefs: " << abort_message << std::endl;
      for (const std::string &path : abort_paths)
        {
          std::error_code ignored;
          std::filesystem::remove_all(path, ignored);
        }
      MPI_Abort(MPI_COMM_WORLD, 1);
    }
  } // namespace

  AbortGuard::AbortGuard(const std::string              &message,
                         const std::vector<std::string> &paths)
  {
    if (guard_alive)
      throw std::logic_error("one AbortGuard at a time");
    abort_message = message;
    abort_paths   = paths;
    guard_alive   = true;
    sc_set_abort_handler(&end_run_on_abort);
  }

  AbortGuard::~AbortGuard()
  {
    sc_set_abort_handler(nullptr);
    guard_alive = false;
  }
} // namespace vefs
