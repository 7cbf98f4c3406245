#include <deal.II/base/mpi.h>

#include <unistd.h>
#include <vefs/io/checkpoint.h>
#include <vefs/io/output_directory.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <system_error>

namespace vefs
{
  namespace
  {
    namespace fs = std::filesystem;

    const std::string lock_name = "vefs.lock";

    /** A file this program writes into the directory. */
    bool
    is_result(const std::string &name)
    {
      const auto ends_with = [&](const std::string &tail) {
        return name.size() >= tail.size() &&
               name.compare(name.size() - tail.size(), tail.size(), tail) == 0;
      };
      return name == "statistics" || name == "parameters.prm" ||
             name == "solution.pvd" || name == CheckpointNames::current ||
             name == CheckpointNames::next ||
             name == CheckpointNames::previous ||
             name == CheckpointNames::damaged ||
             (name.rfind("solution_", 0) == 0 &&
              (ends_with(".vtu") || ends_with(".pvtu")));
    }

    std::string
    host_name()
    {
      char name[256] = {};
      gethostname(name, sizeof(name) - 1);
      return name;
    }

    /**
     * A lock left by a killed run: it names a process of this host that no
     * longer exists. A lock of another host, or unreadable, is kept.
     */
    bool
    is_stale(const std::string &lock)
    {
      std::ifstream input(lock);
      long          pid = 0;
      std::string   host;
      if (!(input >> pid >> host) || pid <= 0 || host != host_name())
        return false;
      return kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH;
    }

    /** "process PID on host HOST", as the lock names it, or "". */
    std::string
    holder(const std::string &lock)
    {
      std::ifstream input(lock);
      long          pid = 0;
      std::string   host;
      if (!(input >> pid >> host) || pid <= 0)
        return "";
      return "process " + std::to_string(pid) + " on host " + host;
    }

    /** Rank 0's work; returns what went wrong, or nothing. */
    std::string
    prepare(const std::string &directory, const bool resume, bool &locked)
    {
      const std::string entry = "entry 'Output directory': ";
      std::error_code   error;
      fs::create_directories(directory, error);
      if (error || !fs::is_directory(directory))
        return entry + "cannot create the directory '" + directory +
               "': " + (error ? error.message() : "a file has this name");

      const std::string lock = directory + "/" + lock_name;
      // "x": fails if the file exists, atomically (C11).
      std::FILE *file = std::fopen(lock.c_str(), "wx");
      if (file == nullptr && is_stale(lock))
        {
          std::cerr << "vefs: warning: removed the lock file '" << lock
                    << "' of a run that no longer runs (it was killed)"
                    << std::endl;
          fs::remove(lock, error);
          file = std::fopen(lock.c_str(), "wx");
        }
      if (file == nullptr && !fs::exists(lock))
        return entry + "cannot write into '" + directory + "'";
      if (file == nullptr)
        {
          // Say whose it is: the user can check that process.
          const std::string who = holder(lock);
          if (who.empty())
            return entry + "'" + lock +
                   "' exists: another run is writing into this directory "
                   "(if none is, a run was killed: remove the file)";
          return entry + "'" + lock + "' exists: the run of " + who +
                 " is writing into this directory (if that process no "
                 "longer runs, it was killed: remove the file)";
        }
      // Who holds the lock: a later run can tell a killed one.
      std::fprintf(file,
                   "%ld %s\n",
                   static_cast<long>(getpid()),
                   host_name().c_str());
      std::fclose(file);
      locked = true;

      // A resumed run continues the results it finds.
      if (resume)
        return "";
      for (const auto &file : fs::directory_iterator(directory, error))
        if (is_result(file.path().filename().string()))
          fs::remove_all(file.path(), error);
      if (error)
        return entry + "cannot remove the results of an earlier run from '" +
               directory + "': " + error.message();
      return "";
    }
  } // namespace

  std::string
  lock_file(const std::string &directory)
  {
    return directory + "/" + lock_name;
  }

  OutputDirectory::OutputDirectory(const std::string &directory,
                                   const MPI_Comm     comm,
                                   const bool         resume)
    : directory(directory)
  {
    std::string problem;
    if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
      problem = prepare(directory, resume, locked);
    // Every rank learns the outcome: none waits for a rank that stopped.
    problem = dealii::Utilities::MPI::broadcast(comm, problem, 0);
    if (!problem.empty())
      {
        if (locked)
          fs::remove(directory + "/" + lock_name);
        locked = false;
        throw InputError(problem);
      }
  }

  OutputDirectory::~OutputDirectory()
  {
    if (locked)
      {
        std::error_code ignored;
        fs::remove(directory + "/" + lock_name, ignored);
      }
  }
} // namespace vefs
