#include <deal.II/base/mpi.h>

#include <vefs/base/errors.h>
#include <vefs/base/stop_signal.h>
#include <vefs/io/checkpoint.h>
#include <vefs/io/checkpoint_schedule.h>

#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace vefs
{
  void
  CheckpointParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Checkpoint");
    {
      prm.add_parameter("Interval steps",
                        checkpoint_interval_steps,
                        "Write a checkpoint (mesh, fields, time and "
                        "statistics position, into <Output directory>/"
                        "checkpoint) after every step whose number is a "
                        "multiple of this; 0: never. A run continues from "
                        "its last checkpoint with 'vefs --resume <Output "
                        "directory>', also on another number of MPI ranks.",
                        Patterns::Integer(0));
      prm.add_parameter("Interval minutes",
                        checkpoint_interval_minutes,
                        "Also write a checkpoint after the step that ends "
                        "this many minutes of wall time after the start (or "
                        "the last checkpoint); 0: never. A SIGTERM or SIGINT "
                        "always writes one after the current step.",
                        Patterns::Double(0));
      prm.add_parameter("Stop after steps",
                        stop_after_steps,
                        "If positive: after this many steps of this "
                        "invocation (counted from the start or from the "
                        "resumed step), write a checkpoint and stop with "
                        "exit status 0 (for jobs with a wall-time limit: "
                        "each job resumes the last one and does this many "
                        "steps); 0: run to the end time.",
                        Patterns::Integer(0));
    }
    prm.leave_subsection();
  }

  CheckpointSchedule::CheckpointSchedule(const CheckpointParameters &parameters,
                                         const std::string &output_directory,
                                         const MPI_Comm     comm,
                                         const ConditionalOStream &pcout)
    : parameters(parameters)
    , output_directory(output_directory)
    , comm(comm)
    , pcout(pcout)
  {
  }

  std::optional<RunEnd>
  CheckpointSchedule::after_step(const unsigned int                  step,
                                 const double                        time,
                                 const unsigned int                  steps_done,
                                 const std::function<std::string()> &write)
  {
    // Every rank takes the same decision.
    const int  signal       = Utilities::MPI::max(received_stop_signal(), comm);
    const bool planned_stop = parameters.stop_after_steps > 0 &&
                              steps_done >= parameters.stop_after_steps;
    const bool by_steps = parameters.checkpoint_interval_steps > 0 &&
                          step % parameters.checkpoint_interval_steps == 0;
    const bool by_time =
      Utilities::MPI::logical_or(parameters.checkpoint_interval_minutes > 0 &&
                                   since_checkpoint.wall_time() >=
                                     60 *
                                       parameters.checkpoint_interval_minutes,
                                 comm);
    if (signal == 0 && !planned_stop && !by_steps && !by_time)
      return {};

    Timer             writing;
    const std::string problem = write();
    if (problem.empty())
      pcout << "checkpoint of step " << step << " written in "
            << std::setprecision(3) << writing.wall_time() << " s" << std::endl;
    since_checkpoint.restart();
    const std::string directory =
      output_directory + "/" + CheckpointNames::current;
    std::ostringstream where;
    where << "step " << step << " (t = " << time << ")";
    // A run that cannot write its checkpoints would lose all since the
    // last one at the next kill: it stops (doc/checkpoints.md, "Full
    // disks").
    if (!problem.empty())
      {
        std::error_code error;
        const bool has_checkpoint = std::filesystem::exists(directory, error);
        throw OutputError(
          "the checkpoint of " + where.str() + " was not written: " + problem +
          "; the statistics end with step " + std::to_string(step) +
          (has_checkpoint ? ", the last checkpoint is in " + directory + "/"
                          : ""));
      }
    const std::string resume_hint = "; the checkpoint is in " + directory +
                                    "/, continue with: vefs --resume " +
                                    output_directory;
    if (signal != 0)
      return RunEnd{128 + signal,
                    std::string("stopped by ") + signal_name(signal) +
                      " after " + where.str() + resume_hint};
    if (planned_stop)
      return RunEnd{0,
                    "stopped after " + where.str() + ", " +
                      std::to_string(steps_done) +
                      " steps as set by 'Checkpoint/Stop after steps'" +
                      resume_hint};
    return {};
  }
} // namespace vefs
