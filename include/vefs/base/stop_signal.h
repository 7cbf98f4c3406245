#ifndef vefs_stop_signal_h
#define vefs_stop_signal_h

namespace vefs
{
  /**
   * Catch SIGTERM and SIGINT: the handler only records the signal, and the
   * time loop writes a checkpoint and stops at the end of the current step.
   * A second signal of the same kind ends the process at once, unless it
   * comes within 1 s (up to 2 s) of the first: then it is the same request
   * delivered twice (coreutils' `timeout` signals the process and its
   * process group).
   */
  void
  install_stop_handlers();

  /** The signal received since install_stop_handlers(), or 0. */
  int
  received_stop_signal();

  /** "SIGTERM", "SIGINT" or "signal N". */
  const char *
  signal_name(const int signal);
} // namespace vefs

#endif
