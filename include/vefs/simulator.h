#ifndef vefs_simulator_h
#define vefs_simulator_h

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/tria.h>

#include <vefs/box_mesh_locator.h>
#include <vefs/liquid_domain.h>
#include <vefs/mesh_adaptation.h>
#include <vefs/output_directory.h>
#include <vefs/parameters.h>
#include <vefs/postprocessing.h>
#include <vefs/rheology.h>
#include <vefs/stokes_step.h>
#include <vefs/transported_fields.h>
#include <vefs/visualization.h>

namespace vefs
{
  /**
   * A free-surface flow in a box-shaped cavity, advanced by the order-one
   * splitting of the design notes (section 2): advection along
   * characteristics, mesh adaptation to the new surface, diffusion on the
   * liquid cells.
   */
  template <int dim>
  class Simulator
  {
  public:
    Simulator(const Parameters &parameters, const ParameterHandler &prm);

    void
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

    double
    choose_time_step(const double max_velocity) const;

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
     * Steps 3 and 4 of the design, then the new velocity extended beyond
     * the liquid for the next characteristics, at least @p expected_cfl
     * cells wide: returns the Krylov iterations.
     */
    unsigned int
    diffusion_step(const LiquidDomain<dim> &domain,
                   const double             new_time,
                   const double             tau,
                   const double             expected_cfl);

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

    const Parameters   &parameters;
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
    /** Solves per step with contact walls, at the most. */
    static constexpr unsigned int max_contact_iterations = 10;
  };
} // namespace vefs

#endif
