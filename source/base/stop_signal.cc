#include <vefs/base/stop_signal.h>

#include <csignal>

namespace vefs
{
  namespace
  {
    volatile std::sig_atomic_t received = 0;

    extern "C" void
    record_signal(int signal)
    {
      if (received == signal)
        {
          // Asked twice: the user does not want to wait for the step.
          std::signal(signal, SIG_DFL);
          std::raise(signal);
          return;
        }
      received = signal;
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
