#ifndef vefs_simulator_h
#define vefs_simulator_h

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/tria.h>

#include <vefs/base/time_control.h>
#include <vefs/compat/box_mesh_locator.h>
#include <vefs/core/parameters.h>
#include <vefs/fields/transported_fields.h>
#include <vefs/flow/stokes_step.h>
#include <vefs/io/checkpoint_schedule.h>
#include <vefs/io/output_directory.h>
#include <vefs/io/postprocessing.h>
#include <vefs/io/visualization.h>
#include <vefs/stress/rheology.h>
#include <vefs/transport/liquid_domain.h>
#include <vefs/transport/mesh_adaptation.h>
#include <vefs/transport/surface_tracker.h>
#include <vefs/transport/velocity_source.h>

#include <functional>
#include <memory>
#include <optional>
#include <string>

namespace vefs
{
  /**
   * A free-surface flow in a box-shaped cavity, advanced by the splitting
   * of doc/method.md ("One time step"): advection along characteristics,
   * mesh adaptation to the new surface, the new velocity on the liquid
   * cells. run() is that loop; the pieces are the time control, the
   * surface tracker and the velocity source (the flow step or a prescribed
   * velocity).
   */
  template <int dim>
  class Simulator
  {
  public:
    /**
     * A new run; or, with @p checkpoint (a directory from find_checkpoint()),
     * the continuation of the run that wrote it, with the parameters it
     * saved.
     */
    Simulator(const Parameters       &parameters,
              const ParameterHandler &prm,
              const std::string      &checkpoint = "");

    RunEnd
    run();

  private:
    /**
     * The cavity, the initial state (or that of the checkpoint) and its
     * statistics row; its liquid domain.
     */
    LiquidDomain<dim>
    start();

    /**
     * The statistics columns of what this scene has: the shape error, the
     * stress, the contact walls, the band placement, the probe.
     */
    void
    add_scene_columns();

    void
    make_cavity();

    void
    set_initial_state();

    /** The state of the checkpoint: mesh, fields, statistics, outputs. */
    void
    resume();

    /**
     * The next step: the velocity source's, landed on the end and output
     * times, checked while the state is still good (else the run stops with
     * the state on @p domain); then started.
     */
    void
    start_step(const LiquidDomain<dim> &domain);

    /**
     * Steps 7-9 on the new liquid @p domain: the velocity source's new
     * velocity (and stress); the run stops if it fails.
     */
    void
    advance_velocity(const LiquidDomain<dim> &domain);

    /**
     * After a step: write a checkpoint if one is due (by the step number,
     * the wall time, a stop signal or 'Stop after steps', the @p steps_done
     * by this invocation); a returned RunEnd stops the run.
     */
    std::optional<RunEnd>
    checkpoint_if_due(const unsigned int steps_done);

    /** Measure, check the health of and write the state of a step. */
    void
    report(const LiquidDomain<dim> &domain);

    /**
     * Say what @p what makes on standard error with the step and time,
     * unless @p said (the warning was given before in this run: the text
     * is not made again); set @p said. Every rank keeps @p said the same.
     */
    void
    warn_once(bool &said, const std::function<std::string()> &what) const;

    /**
     * Run @p solve; if it throws SolverError, stop() the run at the present
     * step with its message after @p context.
     */
    void
    stop_on_solver_error(const std::function<void()> &solve,
                         const std::string           &context,
                         const LiquidDomain<dim>     &domain,
                         const bool                   state_is_good);

    /**
     * Stop the run at @p step with @p problem: write the current state if
     * it is finite (@p state_is_good: it passed every check) and throw
     * SolverError naming the step and what was kept.
     */
    [[noreturn]] void
    stop(const unsigned int       step,
         const std::string       &problem,
         const LiquidDomain<dim> &domain,
         const bool               state_is_good);

    const Parameters &parameters;
    /** The parameters as run, for parameters.prm and the checkpoints. */
    const std::string parameters_text;
    /** Empty for a new run. */
    const std::string   checkpoint;
    const Rheology<dim> rheology;
    const MPI_Comm      comm;
    /** Before the timer: its destructor must not see a failure here. */
    OutputDirectory                           output;
    ConditionalOStream                        pcout;
    mutable TimerOutput                       timer;
    parallel::distributed::Triangulation<dim> triangulation;
    BoundingBox<dim>                          cavity;
    std::unique_ptr<BoxMeshLocator<dim>>      locator;
    MeshLevels                                levels;
    TimeControl                               time;
    TransportedFields<dim>                    fields;
    /** Made with the cavity, which its locator needs. */
    std::unique_ptr<SurfaceTracker<dim>> surface;
    StokesStep<dim>                      flow;
    std::unique_ptr<VelocitySource<dim>> velocity;
    /** The row of the last step: its speeds choose the next step. */
    StepStatistics<dim>            statistics;
    StatisticsFile<dim>            statistics_file;
    Visualization<dim>             visualization;
    EnergyWatch                    energy_watch;
    CheckpointSchedule             checkpoints;
    std::unique_ptr<Function<dim>> exact_final_level_set;
    unsigned int last_output_step = numbers::invalid_unsigned_int;
    /** Whether the probe point was said to lie outside the liquid. */
    bool probe_outside_said = false;
    /** Whether the elastic wave number was said to lie beyond the trusted. */
    bool untrusted_wave_number_said = false;
    /** Whether a conformation tensor was said not to be positive definite. */
    bool  non_positive_conformation_said = false;
    Timer wall_clock;
    /** The wall time of the run before it was resumed. */
    double wall_time_offset = 0;
  };
} // namespace vefs

#endif
