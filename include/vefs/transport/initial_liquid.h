#ifndef vefs_initial_liquid_h
#define vefs_initial_liquid_h

#include <deal.II/base/function.h>

#include <vefs/base/parameters.h>

#include <memory>

namespace vefs
{
  using namespace dealii;

  /**
   * Signed distance (m) to the initial free surface, negative in the liquid:
   * exact for the box and the ball, the user's expression otherwise.
   */
  template <int dim>
  std::unique_ptr<Function<dim>>
  make_initial_level_set(const Parameters &parameters);

  /** Initial velocity field, dim components. */
  template <int dim>
  std::unique_ptr<Function<dim>>
  make_initial_velocity(const Parameters &parameters);

  /**
   * Initial extra stress, components in unrolled order (xx, yy, (zz,) xy,
   * (xz, yz)); nullptr if none is given (zero stress).
   */
  template <int dim>
  std::unique_ptr<Function<dim>>
  make_initial_stress(const Parameters &parameters);

  /** The prescribed velocity of the transport-only mode, time dependent. */
  template <int dim>
  std::unique_ptr<Function<dim>>
  make_prescribed_velocity(const Parameters &parameters);

  /** The exact liquid region at the end time, as a level set. */
  template <int dim>
  std::unique_ptr<Function<dim>>
  make_exact_final_level_set(const Parameters &parameters);

  /** Velocity imposed on a 'velocity' wall, dim components, time dependent. */
  template <int dim>
  std::unique_ptr<Function<dim>>
  make_wall_velocity(const Parameters &parameters, const unsigned int wall);
} // namespace vefs

#endif
