#ifndef vefs_unit_circle_band_h
#define vefs_unit_circle_band_h

// The mesh of the band tests (unit/refine_ahead, unit/band_at_remap): the
// unit square, levels 2 to 6, refined toward a circle's band.

#include <deal.II/base/function.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/grid/grid_generator.h>

#include <vefs/base/cavity.h>
#include <vefs/fields/transported_fields.h>
#include <vefs/transport/level_set_gradient.h>
#include <vefs/transport/mesh_adaptation.h>

namespace unit_test
{
  /** Levels 2 to 6, a band of 2 cells, @p placement. */
  inline vefs::MeshParameters
  circle_band_parameters(const vefs::BandPlacement placement)
  {
    vefs::MeshParameters parameters;
    parameters.min_level                     = 2;
    parameters.bulk_level                    = 2;
    parameters.max_level                     = 6;
    parameters.band_width                    = 2;
    parameters.automatic_band_width          = false;
    parameters.band_placement                = placement;
    parameters.automatic_band_miss_tolerance = false;
    return parameters;
  }

  /** The levels of @p parameters on the unit square, one coarse cell. */
  inline vefs::MeshLevels
  unit_square_levels(const vefs::MeshParameters &parameters)
  {
    vefs::CavityParameters cavity;
    cavity.cavity_lower        = {0, 0};
    cavity.cavity_upper        = {1, 1};
    cavity.coarse_subdivisions = {1, 1};
    return vefs::MeshLevels(parameters, cavity, 2, 1.);
  }

  /**
   * @p mesh, the unit square refined to the minimum level, adapted to the
   * band of @p psi: one level per change, the fields (no stress, no
   * acceleration, set up by the caller) taking @p psi exactly on each mesh,
   * and at the end; the velocity zero, @p gradient zero.
   */
  inline void
  adapt_to_band(dealii::parallel::distributed::Triangulation<2> &mesh,
                vefs::TransportedFields<2>                      &fields,
                vefs::LevelSetGradient<2>                       &gradient,
                const vefs::MeshParameters                      &parameters,
                const vefs::MeshLevels                          &levels,
                const dealii::Function<2>                       &psi)
  {
    const dealii::Functions::ZeroFunction<2> velocity(2);
    for (unsigned int cycle = 0;
         cycle < parameters.max_level - parameters.min_level;
         ++cycle)
      {
        fields.interpolate(psi, velocity);
        gradient.reinit(fields);
        vefs::adapt_mesh(mesh,
                         fields,
                         &gradient,
                         levels,
                         vefs::LevelSetInterpolation::linear);
      }
    fields.interpolate(psi, velocity);
    gradient.reinit(fields);
  }
} // namespace unit_test

#endif
