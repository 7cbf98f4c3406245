#ifndef vefs_initial_liquid_h
#define vefs_initial_liquid_h

#include <deal.II/base/function.h>
#include <deal.II/base/parameter_handler.h>

#include <vefs/base/cavity.h>

#include <memory>
#include <string>
#include <vector>

namespace vefs
{
  using namespace dealii;

  /**
   * The liquid at t = 0: subsection "Initial liquid". The defaults: the
   * water column of the default scene (doc/broken_dam.md).
   */
  struct InitialLiquidParameters
  {
    void
    declare(ParameterHandler &prm);

    /**
     * Throws InputError for a shape that does not fit @p cavity; adds to
     * @p warnings a shape that reaches beyond it.
     */
    void
    check(const unsigned int        dimension,
          const CavityParameters   &cavity,
          std::vector<std::string> &warnings) const;

    std::string         initial_shape        = "box";
    std::vector<double> box_lower            = {0, 0};
    std::vector<double> box_upper            = {0.05715, 0.1143};
    std::vector<double> ball_center          = {0, 0};
    double              ball_radius          = 0.1;
    std::string         level_set_expression = "";
    std::string         initial_velocity     = "0; 0";
    /** Empty: zero initial stress. */
    std::string initial_stress = "";
  };

  /**
   * Signed distance (m) to the initial free surface, negative in the liquid:
   * exact for the box and the ball, the user's expression otherwise.
   */
  template <int dim>
  std::unique_ptr<Function<dim>>
  make_initial_level_set(const InitialLiquidParameters &parameters,
                         const CavityParameters        &cavity);

  /** Initial velocity field, dim components. */
  template <int dim>
  std::unique_ptr<Function<dim>>
  make_initial_velocity(const InitialLiquidParameters &parameters);

  /**
   * Initial extra stress, components in unrolled order (xx, yy, (zz,) xy,
   * (xz, yz)); nullptr if none is given (zero stress).
   */
  template <int dim>
  std::unique_ptr<Function<dim>>
  make_initial_stress(const InitialLiquidParameters &parameters);

  /**
   * The prescribed velocity of the transport-only mode, time dependent, from
   * its 'Transport/Prescribed velocity' @p expression.
   */
  template <int dim>
  std::unique_ptr<Function<dim>>
  make_prescribed_velocity(const std::string &expression);

  /**
   * The exact liquid region at the end time, as a level set, from its
   * 'Transport/Exact final level set' @p expression ('initial': the initial
   * liquid).
   */
  template <int dim>
  std::unique_ptr<Function<dim>>
  make_exact_final_level_set(const std::string             &expression,
                             const InitialLiquidParameters &initial,
                             const CavityParameters        &cavity);

  /** Velocity imposed on a 'velocity' wall, dim components, time dependent. */
  template <int dim>
  std::unique_ptr<Function<dim>>
  make_wall_velocity(const CavityParameters &cavity, const unsigned int wall);
} // namespace vefs

#endif
