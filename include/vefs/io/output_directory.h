#ifndef vefs_output_directory_h
#define vefs_output_directory_h

#include <mpi.h>

#include <string>

namespace vefs
{
  /**
   * The 'Output directory' of a run, held for the lifetime of this object:
   * created if missing, locked by the file vefs.lock (a second run into
   * the same directory is refused; the lock of a killed process of this
   * host is taken over), and cleared of the results of an
   * earlier run (solution*.vtu/pvtu, solution.pvd, statistics,
   * parameters.prm, the checkpoint directories), so that the files of two
   * runs never mix; a @p resume keeps them. Every problem throws InputError
   * on all ranks.
   */
  /** The lock file of the output directory @p directory. */
  std::string
  lock_file(const std::string &directory);

  class OutputDirectory
  {
  public:
    OutputDirectory(const std::string &directory,
                    const MPI_Comm     comm,
                    const bool         resume = false);
    ~OutputDirectory();

    OutputDirectory(const OutputDirectory &) = delete;
    OutputDirectory &
    operator=(const OutputDirectory &) = delete;

    const std::string &
    path() const
    {
      return directory;
    }

  private:
    const std::string directory;
    bool              locked = false;
  };
} // namespace vefs

#endif
