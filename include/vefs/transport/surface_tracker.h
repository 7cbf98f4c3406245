#ifndef vefs_surface_tracker_h
#define vefs_surface_tracker_h

#include <deal.II/base/timer.h>
#include <deal.II/distributed/tria.h>

#include <vefs/base/statistics.h>
#include <vefs/base/time_control.h>
#include <vefs/compat/box_mesh_locator.h>
#include <vefs/fields/transported_fields.h>
#include <vefs/transport/characteristics.h>
#include <vefs/transport/level_set_gradient.h>
#include <vefs/transport/level_set_history.h>
#include <vefs/transport/liquid_domain.h>
#include <vefs/transport/mesh_adaptation.h>
#include <vefs/transport/velocity_source.h>

namespace vefs
{
  /**
   * The free surface from one step to the next (doc/time_step_surface.md,
   * steps 2-6): where the band of finest cells is placed, the
   * advection of every field along the characteristics, the level set
   * history between remaps, the redistancing, the volume correction toward
   * the expected liquid volume, and the mesh adapted to the new surface.
   */
  template <int dim>
  class SurfaceTracker
  {
  public:
    SurfaceTracker(const MeshParameters      &mesh_parameters,
                   const TransportParameters &parameters,
                   const FootInterpolation   &foot_interpolation,
                   parallel::distributed::Triangulation<dim> &triangulation,
                   MeshLevels                                &levels,
                   const BoxMeshLocator<dim>                 &locator,
                   TimerOutput                               &timer);

    /** Register the statistics columns of the band placement. */
    void
    add_columns(StatisticsFile<dim> &statistics) const;

    /**
     * Steps 2-4: with a predicted band, refine ahead of the surface first;
     * then move every field along the characteristics of the step under
     * way in @p time, in the velocity @p velocity gives; at remaps
     * redistance; correct the volume.
     */
    void
    advect(TransportedFields<dim> &fields,
           VelocitySource<dim>    &velocity,
           const TimeControl      &time,
           StepStatistics<dim>    &statistics);

    /**
     * Steps 5-6: at a remap, adapt the mesh to the new surface unless the
     * band kept up with it; the liquid domain of the new mesh.
     */
    LiquidDomain<dim>
    adapt_mesh(TransportedFields<dim> &fields,
               const TimeControl      &time,
               StepStatistics<dim>    &statistics);

    /**
     * Start from the initial @p level_set, which @p fields hold on the
     * initial mesh (its gradient by central differences), and the
     * @p volume of the initial liquid, kept by the correction.
     */
    void
    start(const TransportedFields<dim> &fields,
          const Function<dim>          &level_set,
          const double                  volume);

    /** Continue with the volumes of a checkpoint. */
    void
    resume(const double initial_volume, const double expected_volume);

    /** The liquid @p volume left through open walls. */
    void
    remove_outflow(const double volume);

    double
    initial_volume() const
    {
      return volume_at_start;
    }

    /** The initial volume plus what entered through the walls so far. */
    double
    expected_volume() const
    {
      return volume_expected;
    }

    /** The level set history, for the checkpoints. */
    LevelSetHistory<dim> &
    history()
    {
      return level_set_history;
    }

    const LevelSetHistory<dim> &
    history() const
    {
      return level_set_history;
    }

    /** The level set gradient, for the checkpoints. */
    LevelSetGradient<dim> &
    gradient()
    {
      return level_set_gradient;
    }

    const LevelSetGradient<dim> &
    gradient() const
    {
      return level_set_gradient;
    }

  private:
    const MeshParameters                      &mesh_parameters;
    const TransportParameters                 &parameters;
    parallel::distributed::Triangulation<dim> &triangulation;
    MeshLevels                                &levels;
    const BoxMeshLocator<dim>                 &locator;
    TimerOutput                               &timer;
    const FootInterpolation                    foot_interpolation;
    LevelSetHistory<dim>                       level_set_history;
    /** Carried by the gradient-augmented transport; unread by the others. */
    LevelSetGradient<dim> level_set_gradient;
    /**
     * The fields of the cells the band placement coarsened before the
     * advection, until the advection has read them ('Band placement =
     * predicted, one change'); empty otherwise.
     */
    CoarsenedDetail<dim> coarsened_detail;
    /** Whether the step under way remaps (set by advect()). */
    bool   remap           = true;
    double volume_at_start = 0;
    double volume_expected = 0;
  };
} // namespace vefs

#endif
