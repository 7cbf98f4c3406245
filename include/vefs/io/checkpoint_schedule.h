#ifndef vefs_checkpoint_schedule_h
#define vefs_checkpoint_schedule_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>

#include <functional>
#include <optional>
#include <string>

namespace vefs
{
  using namespace dealii;

  /** How a run ended, if not by an error. */
  struct RunEnd
  {
    /** The exit status: 0, or 128 + the signal that stopped the run. */
    int status = 0;
    /** Where the run stopped and how to continue it; "" if it finished. */
    std::string message;
  };

  /** When checkpoints are written: subsection "Checkpoint". */
  struct CheckpointParameters
  {
    void
    declare(dealii::ParameterHandler &prm);

    unsigned int checkpoint_interval_steps = 0;
    /** 0: no checkpoints by wall time. */
    double checkpoint_interval_minutes = 60;
    /** 0: no planned stop. */
    unsigned int stop_after_steps = 0;
  };

  /**
   * When a run writes a checkpoint (section 'Checkpoint'; README,
   * "Checkpoint and restart"): after every 'Interval steps' steps, after
   * 'Interval minutes' of wall time, on SIGTERM or SIGINT, and before the
   * planned stop of 'Stop after steps'. Every rank takes the same decision.
   */
  class CheckpointSchedule
  {
  public:
    /** @p output_directory: the run's, which holds the checkpoints. */
    CheckpointSchedule(const CheckpointParameters &parameters,
                       const std::string          &output_directory,
                       const MPI_Comm              comm,
                       const ConditionalOStream   &pcout);

    /**
     * After step @p step (at @p time), the @p steps_done -th of this
     * invocation: write a checkpoint with @p write if one is due (it
     * returns what went wrong, or ""); a returned RunEnd stops the run.
     * A checkpoint that fails to be written stops the run only if the run
     * was to stop anyway (then with SolverError), else it is a warning.
     */
    std::optional<RunEnd>
    after_step(const unsigned int                  step,
               const double                        time,
               const unsigned int                  steps_done,
               const std::function<std::string()> &write);

  private:
    const CheckpointParameters &parameters;
    const std::string           output_directory;
    const MPI_Comm              comm;
    const ConditionalOStream   &pcout;
    /** Wall time since the start or the last checkpoint. */
    Timer since_checkpoint;
  };
} // namespace vefs

#endif
