#include <vefs/transport/redistancing.h>
#include <vefs/transport/surface_tracker.h>
#include <vefs/transport/volume_correction.h>

#include <algorithm>

namespace vefs
{
  template <int dim>
  SurfaceTracker<dim>::SurfaceTracker(
    const MeshParameters                      &mesh_parameters,
    const TransportParameters                 &parameters,
    const FootInterpolation                   &foot_interpolation,
    parallel::distributed::Triangulation<dim> &triangulation,
    MeshLevels                                &levels,
    const BoxMeshLocator<dim>                 &locator,
    TimerOutput                               &timer)
    : mesh_parameters(mesh_parameters)
    , parameters(parameters)
    , triangulation(triangulation)
    , levels(levels)
    , locator(locator)
    , timer(timer)
    , foot_interpolation(foot_interpolation)
    , level_set_history(parameters.remap_distance)
  {
  }

  template <int dim>
  void
  SurfaceTracker<dim>::add_columns(StatisticsFile<dim> &statistics) const
  {
    if (mesh_parameters.band_predicted())
      statistics.add_column("advected_cells",
                            [](const auto &s) { return s.advected_cells; });
  }

  template <int dim>
  void
  SurfaceTracker<dim>::advect(TransportedFields<dim> &fields,
                              VelocitySource<dim>    &velocity,
                              const TimeControl      &time,
                              StepStatistics<dim>    &statistics)
  {
    const double tau        = time.tau();
    statistics.mesh_changes = 0;
    if (mesh_parameters.band_predicted())
      {
        // Refine where the surface will be before it gets there: the band
        // need not be widened by the CFL number.
        typename TransportedFields<dim>::VectorType surface_ahead;
        {
          TimerOutput::Scope scope(timer, "1 advection: predict");
          velocity.set_advection_velocity(fields, time);
          surface_ahead = predict_level_set(fields, tau, locator);
        }
        TimerOutput::Scope scope(timer, "1 advection: refine ahead");
        statistics.mesh_changes +=
          refine_ahead_of_surface(triangulation,
                                  fields,
                                  level_set_gradient,
                                  levels,
                                  levels.max_level - levels.min_level,
                                  parameters.level_set_interpolation,
                                  surface_ahead,
                                  mesh_parameters.band_in_one_change(),
                                  mesh_parameters.band_miss_tolerance,
                                  coarsened_detail);
        statistics.advected_cells = triangulation.n_global_active_cells();
      }

    // Between remaps the level set is the one of the last remap through
    // all steps since (LevelSetHistory).
    TimerOutput::Scope scope(timer, "1 advection");
    velocity.set_advection_velocity(fields, time);
    level_set_history.add_step(fields, tau);
    advect_along_characteristics(fields,
                                 level_set_gradient,
                                 tau,
                                 locator,
                                 foot_interpolation,
                                 &coarsened_detail);
    velocity.finish_advection(fields, time);
    coarsened_detail.clear();
    remap = true;
    if (level_set_history.enabled())
      {
        level_set_history.compose(fields,
                                  level_set_gradient,
                                  locator,
                                  parameters.level_set_interpolation);
        remap = level_set_history.remap_due(time.cfl(), time.expected_cfl());
      }
    if (remap && parameters.redistancing_interval > 0 &&
        time.step() % parameters.redistancing_interval == 0)
      // Within 2R cells (R the remap distance) the characteristics of the
      // next remaps read the level set; a distance has kinks inside thin
      // filaments there (2D; doc/transport.md, "Redistancing from a distance
      // function").
      redistance(fields,
                 level_set_gradient,
                 parameters.level_set_interpolation,
                 parameters.kept_at_redistancing(dim) *
                   levels.finest_cell_size);
    if (parameters.volume_correction)
      {
        const double shift = correct_volume(fields,
                                            volume_expected,
                                            parameters.volume_correction_shift);
        if (!remap)
          level_set_history.shift_base(fields, shift);
      }
  }

  template <int dim>
  LiquidDomain<dim>
  SurfaceTracker<dim>::adapt_mesh(TransportedFields<dim> &fields,
                                  const TimeControl      &time,
                                  StepStatistics<dim>    &statistics)
  {
    // Refined and coarsened in one change before the advection, the mesh
    // changes again only where the surface left the finest cells in more
    // than 'Band miss tolerance' of its cells.
    TimerOutput::Scope scope(timer, "2 mesh adaptation");
    const SurfaceCells surface =
      count_surface_cells(fields, mesh_parameters.max_level);
    statistics.coarse_surface_cells = surface.coarse;
    if (remap && (!mesh_parameters.band_in_one_change() ||
                  !surface.within(mesh_parameters.band_miss_tolerance)))
      {
        levels.expect_cfl(std::max(time.expected_cfl(),
                                   level_set_history.cells_between_remaps()));
        // A cycle moves a cell by one level. Remapped every step, the
        // surface moves less than the band is wide, and one cycle keeps it
        // in the finest cells. Between remaps it moves up to the remap
        // distance, beyond the band's graded rim, into cells that one cycle
        // a remap had not yet brought to the finest level (the vortex at
        // h = 1/128, CFL 1: up to 46 surface cells coarser than the finest,
        // doc/transport.md): refine until the band is complete. Further
        // cycles only refine: coarsening would undo what the 2:1 balance
        // refined in the cycle before.
        const unsigned int cycles =
          level_set_history.enabled() ? levels.max_level - levels.min_level : 1;
        unsigned int changes = 0;
        while (changes < cycles &&
               vefs::adapt_mesh<dim>(triangulation,
                                     fields,
                                     &level_set_gradient,
                                     levels,
                                     parameters.level_set_interpolation,
                                     nullptr,
                                     changes == 0 ? PresentBand::kept
                                                  : PresentBand::refine_only))
          ++changes;
        statistics.mesh_changes += changes;
        if (changes > 0)
          {
            // Restore the volume on the new mesh (doc/time_step_surface.md,
            // step 4) where the change can have moved it: with a cubic level
            // set the new nodes of refined cells take cubic values, and a
            // Q1 level set keeps its surface but not its measured volume
            // where cut cells were refined: the quadrature of a cut cell is
            // not exact for its trilinear surface, and a cell's differs from
            // its children's (the 3D ball: |dV/V| up to 1e-6 in one step).
            // Without coarse cut cells the Q1 liquid is the same: no second
            // volume integral.
            if (parameters.volume_correction &&
                (surface.coarse > 0 || parameters.level_set_interpolation !=
                                         LevelSetInterpolation::linear))
              correct_volume(fields,
                             volume_expected,
                             parameters.volume_correction_shift);
          }
        level_set_history.remap(fields, level_set_gradient);
      }
    return LiquidDomain<dim>(fields);
  }

  template <int dim>
  void
  SurfaceTracker<dim>::start(const TransportedFields<dim> &fields,
                             const Function<dim>          &level_set,
                             const double                  volume)
  {
    level_set_gradient.interpolate(fields, level_set);
    volume_at_start = volume;
    volume_expected = volume;
  }

  template <int dim>
  void
  SurfaceTracker<dim>::resume(const double initial_volume,
                              const double expected_volume)
  {
    volume_at_start = initial_volume;
    volume_expected = expected_volume;
  }

  template <int dim>
  void
  SurfaceTracker<dim>::remove_outflow(const double volume)
  {
    volume_expected -= volume;
  }

  template class SurfaceTracker<2>;
  template class SurfaceTracker<3>;
} // namespace vefs
