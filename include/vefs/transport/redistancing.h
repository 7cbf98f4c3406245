#ifndef vefs_redistancing_h
#define vefs_redistancing_h

#include <vefs/fields/transported_fields.h>
#include <vefs/transport/level_set_gradient.h>
#include <vefs/transport/transport_parameters.h>

namespace vefs
{
  /**
   * Make the level set a signed distance again away from the free surface.
   * Advection along characteristics stretches psi, and where the liquid has
   * left, psi keeps small values that would hold the finest mesh there.
   * The nodes of cells cut by the surface keep their values, so the zero
   * level set (and the volume) does not move; every other node gets the
   * distance to the surface's crossings of cell edges, gathered from all
   * ranks, with the sign it had. The crossings are those of the level set as
   * the transport interpolates it (@p interpolation: Q1, or cubic Hermite,
   * whose zero set differs from the Q1 one by O(h^2)); the
   * @p level_set_gradient of those nodes becomes the unit vector away from
   * the nearest crossing. Nodes nearer the surface than @p kept_distance
   * keep their values too: the characteristics of the next remaps read them
   * (doc/transport.md, "Redistancing from a distance function").
   */
  template <int dim>
  void
  redistance(TransportedFields<dim>     &fields,
             LevelSetGradient<dim>      &level_set_gradient,
             const LevelSetInterpolation interpolation,
             const double                kept_distance = 0);
} // namespace vefs

#endif
