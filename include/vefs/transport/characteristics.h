#ifndef vefs_characteristics_h
#define vefs_characteristics_h

#include <deal.II/base/bounding_box.h>

#include <vefs/compat/box_mesh_locator.h>
#include <vefs/fields/coarsened_detail.h>
#include <vefs/fields/transported_fields.h>
#include <vefs/transport/level_set_gradient.h>
#include <vefs/transport/transport_parameters.h>

#include <array>
#include <utility>
#include <vector>

namespace vefs
{
  /** How each field is interpolated at the feet of the characteristics. */
  struct FootInterpolation
  {
    LevelSetInterpolation level_set = LevelSetInterpolation::linear;
    VelocityInterpolation velocity  = VelocityInterpolation::linear;
    /** Limited cubic stress, where c = I + sigma / G stays positive. */
    bool   cubic_stress  = false;
    double shear_modulus = 1;

    /**
     * @p has_stress: whether the material carries a stress;
     * @p shear_modulus: Rheology::shear_modulus(), used with a stress.
     */
    FootInterpolation(const TransportParameters &parameters,
                      const bool                 has_stress,
                      const double               shear_modulus)
      : level_set(parameters.level_set_interpolation)
      , velocity(parameters.velocity_interpolation)
      , cubic_stress(parameters.cubic_stress_interpolation() && has_stress)
      , shear_modulus(cubic_stress ? shear_modulus : 1.)
    {
      Assert(velocity != VelocityInterpolation::automatic,
             dealii::ExcMessage("TransportParameters::resolve() first."));
    }
  };

  /**
   * Advection step of the splitting (doc/time_step_surface.md,
   * step 2): every field takes at a node x its old value at the foot of the
   * characteristic,
   *   X(x) = x - tau u(x - tau/2 u(x)),
   * a two-stage trace, second order in the foot position (with the
   * gradient-augmented level set a four-stage Runge-Kutta trace, whose
   * Jacobian J = dX/dx updates the level set gradient). Feet may lie many
   * cells away: in the local part of the mesh the locator finds their cell;
   * feet in cells of other MPI ranks go to the rank p4est names. Feet
   * outside the cavity are moved back onto its walls, or wrapped around
   * periodic walls.
   * The fields are interpolated at the feet as @p interpolation says
   * (FieldHermite for the cubic ones); in the cells the last mesh change
   * coarsened, in their former children if @p coarsened_detail holds them.
   */
  template <int dim>
  void
  advect_along_characteristics(
    TransportedFields<dim>     &fields,
    LevelSetGradient<dim>      &level_set_gradient,
    const double                tau,
    const BoxMeshLocator<dim>  &locator,
    const FootInterpolation    &interpolation,
    const CoarsenedDetail<dim> *coarsened_detail = nullptr);

  /**
   * One step of the trace above for arbitrary @p points (four stages, in
   * the frozen velocity that @p fields hold, with its nodal gradient
   * @p velocity_gradient from recover_nodal_gradients()): @p points become
   * their feet, moved back into the cavity; J = dX/dx is multiplied onto
   * @p jacobians from the left (if not null), and @p beyond_contact keeps
   * the largest distance of a foot beyond a contact wall. Tracing the newest
   * step first composes the traces of several steps (LevelSetHistory).
   */
  template <int dim>
  void
  trace_back(const TransportedFields<dim> &fields,
             const std::array<typename TransportedFields<dim>::VectorType, dim>
                                         &velocity_gradient,
             const double                 tau,
             const BoxMeshLocator<dim>   &locator,
             std::vector<Point<dim>>     &points,
             std::vector<Tensor<2, dim>> *jacobians,
             std::vector<double>         &beyond_contact);

  /**
   * Where the surface will be after the next advection, without changing
   * @p fields: the Q1 level set at the feet of the two-stage trace of every
   * node, in the level set slot of a vector with the layout of the fields
   * (the other slots are zero). For refining the mesh ahead of the surface
   * ('Band placement = predicted').
   */
  template <int dim>
  typename TransportedFields<dim>::VectorType
  predict_level_set(const TransportedFields<dim> &fields,
                    const double                  tau,
                    const BoxMeshLocator<dim>    &locator);

  /**
   * The level set of @p fields at @p points anywhere in the mesh,
   * interpolated as @p interpolation says, with its gradient (gradient
   * augmented only; zero otherwise).
   */
  template <int dim>
  std::vector<std::pair<double, Tensor<1, dim>>>
  level_set_at(const TransportedFields<dim>  &fields,
               const LevelSetGradient<dim>   &level_set_gradient,
               const std::vector<Point<dim>> &points,
               const BoxMeshLocator<dim>     &locator,
               const LevelSetInterpolation    interpolation);
} // namespace vefs

#endif
