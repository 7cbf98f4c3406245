// A full disk for the tests (tests/full_disk.cmd): preloaded with
// LD_PRELOAD, every write to a file whose path contains the text of the
// environment variable VEFS_WRITE_FAULT fails with ENOSPC, as on a full
// disk; other files (and every file without the variable) are written as
// usual. It wraps the write calls that libstdc++ (write, writev), Open
// MPI's MPI-IO (pwrite, pwritev) and p4est (fwrite) make through the C
// library.

#include <dlfcn.h>
#include <sys/types.h>
#include <sys/uio.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace
{
  bool
  faulty(const int fd)
  {
    const char *pattern = std::getenv("VEFS_WRITE_FAULT");
    if (pattern == nullptr || *pattern == '\0')
      return false;
    char link[64], path[4096];
    std::snprintf(link, sizeof(link), "/proc/self/fd/%d", fd);
    const ssize_t length = readlink(link, path, sizeof(path) - 1);
    if (length <= 0)
      return false;
    path[length] = '\0';
    return std::strstr(path, pattern) != nullptr;
  }

  template <typename Function>
  Function
  next(const char *name)
  {
    return reinterpret_cast<Function>(dlsym(RTLD_NEXT, name));
  }
} // namespace

extern "C"
{
  ssize_t
  write(int fd, const void *buffer, size_t count)
  {
    if (faulty(fd))
      {
        errno = ENOSPC;
        return -1;
      }
    static const auto real =
      next<ssize_t (*)(int, const void *, size_t)>("write");
    return real(fd, buffer, count);
  }

  ssize_t
  writev(int fd, const struct iovec *vectors, int count)
  {
    if (faulty(fd))
      {
        errno = ENOSPC;
        return -1;
      }
    static const auto real =
      next<ssize_t (*)(int, const struct iovec *, int)>("writev");
    return real(fd, vectors, count);
  }

  ssize_t
  pwrite(int fd, const void *buffer, size_t count, off_t offset)
  {
    if (faulty(fd))
      {
        errno = ENOSPC;
        return -1;
      }
    static const auto real =
      next<ssize_t (*)(int, const void *, size_t, off_t)>("pwrite");
    return real(fd, buffer, count, offset);
  }

  ssize_t
  pwritev(int fd, const struct iovec *vectors, int count, off_t offset)
  {
    if (faulty(fd))
      {
        errno = ENOSPC;
        return -1;
      }
    static const auto real =
      next<ssize_t (*)(int, const struct iovec *, int, off_t)>("pwritev");
    return real(fd, vectors, count, offset);
  }

  size_t
  fwrite(const void *buffer, size_t size, size_t count, FILE *stream)
  {
    if (faulty(fileno(stream)))
      {
        errno = ENOSPC;
        return 0;
      }
    static const auto real =
      next<size_t (*)(const void *, size_t, size_t, FILE *)>("fwrite");
    return real(buffer, size, count, stream);
  }

  ssize_t
  pwrite64(int fd, const void *buffer, size_t count, off64_t offset)
  {
    if (faulty(fd))
      {
        errno = ENOSPC;
        return -1;
      }
    static const auto real =
      next<ssize_t (*)(int, const void *, size_t, off64_t)>("pwrite64");
    return real(fd, buffer, count, offset);
  }
}
