#ifndef vefs_simulator_h
#define vefs_simulator_h

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/tria.h>

#include <vefs/box_mesh_locator.h>
#include <vefs/checkpoint.h>
#include <vefs/level_set_history.h>
#include <vefs/liquid_domain.h>
#include <vefs/mesh_adaptation.h>
#include <vefs/output_directory.h>
#include <vefs/parameters.h>
#include <vefs/postprocessing.h>
#include <vefs/rheology.h>
#include <vefs/stokes_step.h>
#include <vefs/transported_fields.h>
#include <vefs/visualization.h>

#include <optional>
#include <string>

namespace vefs
{
  /**
   * A free-surface flow in a box-shaped cavity, advanced by the order-one
   * splitting of doc/method.md ("One time step"): advection along
   * characteristics, mesh adaptation to the new surface, diffusion on the
   * liquid cells.
   */
  /** How a run ended, if not by an error. */
  struct RunEnd
  {
    /** The exit status: 0, or 128 + the signal that stopped the run. */
    int status = 0;
    /** Where the run stopped and how to continue it; "" if it finished. */
    std::string message;
  };

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
     * The statistics columns of what this scene has: the shape error, the
     * stress, the contact walls, the probe.
     */
    void
    add_scene_columns();

    void
    make_cavity();

    void
    set_initial_state();

    /** The state of the checkpoint: mesh, fields, statistics, outputs. */
    StepStatistics<dim>
    resume();

    /**
     * After a step: write a checkpoint if one is due (by the step number,
     * the wall time, a stop signal or 'Stop after steps', the @p steps_done
     * by this invocation); a returned RunEnd stops the run.
     */
    std::optional<RunEnd>
    checkpoint_if_due(const StepStatistics<dim> &statistics,
                      const unsigned int         steps_done);

    /**
     * The next time step from the speeds of the @p last one: 'Time step',
     * bounded by the target CFL number and the largest strain per step.
     */
    double
    choose_time_step(const StepStatistics<dim> &last) const;

    /** The length of the next step, and the flow's step it came from. */
    struct StepLength
    {
      double tau;
      /** The step the CFL and strain bounds allow, before the end time and
       * output times shorten it (the health check watches it). */
      double controlled;
    };

    /** The next step after @p statistics: the flow's (or the prescribed
     * velocity's) step, shortened to land on the end and output times. */
    StepLength
    choose_step_length(const StepStatistics<dim> &statistics) const;

    /** The first multiple of 'Output/Time interval' after @p time. */
    double
    next_output_time(const double time) const;

    /** Whether this step writes visualization files. */
    bool
    is_output_step(const StepStatistics<dim> &statistics) const;

    /** Largest prescribed speed in the liquid at @p time. */
    double
    prescribed_speed(const double time) const;

    /**
     * Time step with a prescribed velocity: the target CFL number holds
     * for the speed over the whole step, not only at its start.
     */
    double
    choose_prescribed_time_step(const double time) const;

    /**
     * Steps 7-9 of doc/method.md ("One time step"): the Stokes step, the
     * stress update, then the new velocity extended beyond
     * the liquid for the next characteristics, at least @p expected_cfl
     * cells wide. Records the Krylov iterations and what the stress update
     * reports in @p statistics.
     */
    void
    diffusion_step(const LiquidDomain<dim> &domain,
                   const double             new_time,
                   const double             tau,
                   const double             expected_cfl,
                   StepStatistics<dim>     &statistics);

    /** The regime and the mode, for the banner. */
    std::string
    description() const;

    bool
    is_last_step(const StepStatistics<dim> &statistics) const
    {
      return statistics.time >= parameters.end_time * (1 - 1e-12);
    }

    /** Measure, check the health of and write the state of a step. */
    void
    report(StepStatistics<dim> &statistics, const LiquidDomain<dim> &domain);

    /**
     * Stop the run at @p step with @p problem: write the current state if
     * it is finite (@p state_is_good: it passed every check) and throw
     * SolverError naming the step and what was kept.
     */
    [[noreturn]] void
    stop(const unsigned int         step,
         const StepStatistics<dim> &statistics,
         const std::string         &problem,
         const LiquidDomain<dim>   &domain,
         const bool                 state_is_good);

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
    TransportedFields<dim>                    fields;
    LevelSetHistory<dim>                      level_set_history;
    StokesStep<dim>                           flow;
    StatisticsFile<dim>                       statistics_file;
    Visualization<dim>                        visualization;
    std::unique_ptr<Function<dim>>            prescribed_velocity;
    std::unique_ptr<Function<dim>>            exact_final_level_set;
    double                                    initial_volume = 0;
    /** The initial volume plus what entered through the walls so far. */
    double       expected_volume  = 0;
    unsigned int last_output_step = numbers::invalid_unsigned_int;
    Timer        wall_clock;
    /** The wall time of the run before it was resumed. */
    double wall_time_offset = 0;
    Timer  since_checkpoint;
    /** Solves per step with contact walls, at the most. */
    static constexpr unsigned int max_contact_iterations = 10;
    /** The shortest step before an end or output time, as a fraction of the
     * step before it. */
    static constexpr double min_step_fraction = 0.25;
  };
} // namespace vefs

#endif
