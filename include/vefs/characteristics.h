#ifndef vefs_characteristics_h
#define vefs_characteristics_h

#include <deal.II/base/bounding_box.h>

#include <vefs/box_mesh_locator.h>
#include <vefs/transported_fields.h>

namespace vefs
{
  /**
   * Advection step of the splitting (design section 2, step 1): every field
   * takes at a node x its old value at the foot of the characteristic,
   *   X(x) = x - tau u(x - tau/2 u(x)),
   * a two-stage trace, second order in the foot position (with the
   * gradient-augmented level set a four-stage Runge-Kutta trace, whose
   * Jacobian J = dX/dx updates the level set gradient). Feet may lie many
   * cells away: in the local part of the mesh the locator finds their cell,
   * on other MPI ranks RemotePointEvaluation does. Feet outside the cavity
   * are moved back onto its walls, or wrapped around periodic walls.
   * The level set is interpolated at the feet as @p interpolation says
   * (LevelSetHermite for the cubic ones), the other fields linearly (Q1).
   */
  template <int dim>
  void
  advect_along_characteristics(TransportedFields<dim>     &fields,
                               const double                tau,
                               const BoxMeshLocator<dim>  &locator,
                               const LevelSetInterpolation interpolation);
} // namespace vefs

#endif
