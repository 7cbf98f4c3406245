#include <deal.II/base/mpi.h>

#include <vefs/base/errors.h>
#include <vefs/base/write_failure.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>

namespace vefs
{
  std::string
  write_failure_cause(const int error_number)
  {
    if (error_number == ENOSPC)
      return "no space left on the device";
    if (error_number == EFBIG)
      return "the file would exceed the size this process may write "
             "(ulimit -f)";
    if (error_number == 0)
      return "the write failed";
    return std::strerror(error_number);
  }

  std::string
  write_failure(const std::string &path)
  {
    return "cannot write '" + path + "': " + write_failure_cause(errno);
  }

  std::string
  checked_write(const std::string                         &path,
                const std::function<void(std::ostream &)> &write)
  {
    errno = 0;
    std::ofstream out(path, std::ios::binary);
    if (!out)
      return write_failure(path);
    try
      {
        write(out);
      }
    catch (...)
      {
        // deal.II's writers throw ExcIO when the stream failed: that
        // failure is reported below; any other goes on.
        if (out)
          throw;
      }
    out.close();
    return out ? std::string() : write_failure(path);
  }

  void
  throw_if_write_failed(const std::string &problem,
                        const std::string &where,
                        const MPI_Comm     comm)
  {
    // One reduction when all went well; the texts only when one did not.
    if (!dealii::Utilities::MPI::logical_or(!problem.empty(), comm))
      return;
    for (const std::string &text :
         dealii::Utilities::MPI::all_gather(comm, problem))
      if (!text.empty())
        throw OutputError(text + " " + where);
  }

  std::uintmax_t
  free_bytes(const std::string &path)
  {
    std::error_code error;
    const auto      space = std::filesystem::space(path, error);
    return error ? std::numeric_limits<std::uintmax_t>::max() : space.available;
  }
} // namespace vefs
