#ifndef vefs_gradient_consistency_h
#define vefs_gradient_consistency_h

#include <deal.II/base/types.h>

#include <vefs/fields/transported_fields.h>
#include <vefs/transport/level_set_gradient.h>

namespace vefs
{
  /**
   * The gradient-augmented level set carries grad psi with the Jacobian of
   * the feet, which comes from the recovered gradient of the velocity. In a
   * flow that velocity is only piecewise smooth near the surface (the
   * extension beyond the liquid, the walls, the cut cells), and in thin
   * jets the carried gradient can drift away from the values it belongs to:
   * the Hermite cubic between the nodes then bulges and the advection makes
   * liquid (doc/transport_in_flows.md, "What holds it in flows").
   *
   * At every owned node, the carried gradient g is compared with the
   * gradient r of the Q1 values (the mean of the cells' Q1 gradients around
   * the node, FieldHermite's recovered one); where |g - r| exceeds
   * @p bound * max(1, |r|), g becomes r. Where the level set is smooth on
   * the scale of a cell, g and r agree to O(h) and nothing changes; in a
   * filament thinner than a cell g holds what r cannot, and the bound must
   * leave it (with 1 the vortex and Zalesak's disk keep their shape errors
   * to the last digit, doc/transport_in_flows.md).
   * Returns the number of nodes changed, over all ranks.
   */
  template <int dim>
  types::global_dof_index
  hold_gradient_to_values(const TransportedFields<dim> &fields,
                          LevelSetGradient<dim>        &level_set_gradient,
                          const double                  bound);
} // namespace vefs

#endif
