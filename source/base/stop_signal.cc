#include <vefs/base/stop_signal.h>

#include <csignal>
#include <ctime>

namespace vefs
{
  namespace
  {
    volatile std::sig_atomic_t received = 0;
    /** When the first signal came (CLOCK_MONOTONIC, seconds). */
    volatile std::sig_atomic_t received_at = 0;

    /** clock_gettime() may be called in a signal handler (POSIX). */
    long
    now()
    {
      timespec time{};
      clock_gettime(CLOCK_MONOTONIC, &time);
      return static_cast<long>(time.tv_sec);
    }

    extern "C" void
    record_signal(int signal)
    {
      if (received == signal)
        {
          // The same request sent twice within a moment: coreutils'
          // `timeout` signals the process and then its process group, a
          // terminal the group that mpirun signals too. Not a second ask.
          if (now() - received_at <= 1)
            return;
          // Asked twice: the user does not want to wait for the step.
          std::signal(signal, SIG_DFL);
          std::raise(signal);
          return;
        }
      received    = signal;
      received_at = static_cast<std::sig_atomic_t>(now());
    }
  } // namespace

  void
  install_stop_handlers()
  {
    std::signal(SIGTERM, record_signal);
    std::signal(SIGINT, record_signal);
  }

  int
  received_stop_signal()
  {
    return received;
  }

  const char *
  signal_name(const int signal)
  {
    switch (signal)
      {
        case SIGTERM:
          return "SIGTERM";
        case SIGINT:
          return "SIGINT";
      }
    return "a signal";
  }
} // namespace vefs
