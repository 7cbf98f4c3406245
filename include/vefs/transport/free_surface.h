#ifndef vefs_free_surface_h
#define vefs_free_surface_h

#include <vefs/fields/transported_fields.h>

namespace vefs
{
  /**
   * L1 error of the liquid region, int |phi - phi_exact|, with phi_exact the
   * indicator of @p exact_level_set < 0 (assumed 1-Lipschitz, like a
   * distance) and both indicators sharp.
   */
  template <int dim>
  double
  shape_error(const TransportedFields<dim> &fields,
              const Function<dim>          &exact_level_set);

  /**
   * Thickness of the free surface in the transport's smoothed indicator
   * phi = H(-psi), integrated per cell with a sub-cell rule and a Heaviside
   * smoothed over one sub-cell: the volume of the partly filled cells
   * (0.01 < fraction < 0.99) per unit surface area (int delta(psi)
   * |grad psi|), divided by the finest cell size. About one for a sharp
   * surface. (The volume of the statistics and of the volume correction is
   * the sharp one of the flow step, sharp_liquid_volume().)
   */
  template <int dim>
  double
  interface_thickness(const TransportedFields<dim> &fields,
                      const double                  finest_cell_size);

  /** Largest coordinate @p coordinate of the liquid on wall @p boundary_id. */
  template <int dim>
  double
  liquid_extent_on_wall(const TransportedFields<dim> &fields,
                        const types::boundary_id      boundary_id,
                        const unsigned int            coordinate,
                        const double                  value_if_dry);
} // namespace vefs

#endif
