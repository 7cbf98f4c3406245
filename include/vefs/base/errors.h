#ifndef vefs_errors_h
#define vefs_errors_h

#include <stdexcept>

namespace vefs
{
  /**
   * The four ways a run stops with a message instead of a result; main()
   * prints the message and exits with a non-zero status. They live on the
   * ground floor so that any module may throw them without depending on the
   * module that reads the input, writes the checkpoints or solves the flow.
   */

  /**
   * A problem with the user's input: reported as one message naming the
   * entry and what is allowed, then the run stops with a non-zero status.
   */
  class InputError : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /** A checkpoint that cannot be resumed: the run stops with this message. */
  class CheckpointError : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /**
   * A step that failed (a solver that did not converge, a state that is not
   * finite): the run stops with this message.
   */
  class SolverError : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /**
   * A result that could not be written (a full disk): the run stops with
   * this message, which names the file, the step and the cause.
   */
  class OutputError : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };
} // namespace vefs

#endif
