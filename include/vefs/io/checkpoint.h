#ifndef vefs_checkpoint_h
#define vefs_checkpoint_h

#include <deal.II/distributed/tria.h>

#include <vefs/base/errors.h>
#include <vefs/base/statistics.h>
#include <vefs/fields/transported_fields.h>
#include <vefs/transport/level_set_history.h>

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace vefs
{
  /**
   * What the time loop carries from one step to the next besides the mesh
   * and the transported fields. Of the statistics only the step, time, tau,
   * cfl, max_velocity and max_velocity_gradient (they set the next time
   * step), linear_iterations and
   * wall_time are kept: the others are measured again every step.
   */
  template <int dim>
  struct RunState
  {
    StepStatistics<dim> statistics;
    double              initial_volume  = 0;
    double              expected_volume = 0;
    unsigned int        last_output_step;
    /** The solution.pvd series: (time, .pvtu file). */
    std::vector<std::pair<double, std::string>> visualization_series;
    /** ContactWalls::saved_state(): where the next contact set starts. */
    std::vector<Point<dim>> contact_state;
  };

  /** Names of the checkpoint directories inside an output directory. */
  struct CheckpointNames
  {
    static constexpr const char *current = "checkpoint";
    /** Being written. */
    static constexpr const char *next = "checkpoint.new";
    /** The one before: kept, for a newest one that is damaged. */
    static constexpr const char *previous = "checkpoint.old";
    /** A damaged checkpoint/ set aside by a resume from the one before. */
    static constexpr const char *damaged = "checkpoint.damaged";
  };

  /**
   * The intact checkpoint in @p output_directory, every file checked
   * against the checksums of its state file: checkpoint/, else
   * checkpoint.old/ (the one before, or the only one if the run was killed
   * between the two renames that replace it; a warning on stderr says why
   * checkpoint/ was passed over). Throws InputError, on all ranks of
   * @p comm, if there is none. Collective.
   */
  std::string
  find_checkpoint(const std::string &output_directory, const MPI_Comm comm);

  /**
   * Write the mesh, the fields, the @p level_set_gradient, the level set
   * @p history, @p state and the
   * parameters of the run (@p parameters_text) into checkpoint.new/ of
   * @p output_directory, then
   * make it checkpoint/ by renaming: a kill at any moment leaves a complete
   * checkpoint. Collective; returns what went wrong, or "" (on all ranks).
   */
  template <int dim>
  std::string
  write_checkpoint(const std::string            &output_directory,
                   const std::string            &parameters_text,
                   const TransportedFields<dim> &fields,
                   const LevelSetGradient<dim>  &level_set_gradient,
                   const LevelSetHistory<dim>   &history,
                   const RunState<dim>          &state);

  /**
   * Load the mesh and the fields of the checkpoint in @p directory (from
   * find_checkpoint()) into @p triangulation, which holds the coarse mesh
   * only, @p fields, @p level_set_gradient and @p history; return the
   * state. Any number of ranks
   * (a checkpoint without a history line, as written before the remap
   * distance, leaves the history empty). Throws
   * CheckpointError, on all ranks, if the checkpoint is incomplete or
   * damaged.
   */
  template <int dim>
  RunState<dim>
  read_checkpoint(const std::string                         &directory,
                  parallel::distributed::Triangulation<dim> &triangulation,
                  TransportedFields<dim>                    &fields,
                  LevelSetGradient<dim>                     &level_set_gradient,
                  LevelSetHistory<dim>                      &history);
} // namespace vefs

#endif
