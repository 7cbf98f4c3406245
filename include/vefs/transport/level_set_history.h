#ifndef vefs_level_set_history_h
#define vefs_level_set_history_h

#include <vefs/compat/box_mesh_locator.h>
#include <vefs/fields/transported_fields.h>
#include <vefs/transport/level_set_gradient.h>
#include <vefs/transport/transport_parameters.h>

#include <array>
#include <deque>
#include <vector>

namespace vefs
{
  /**
   * The level set between two remaps (entry 'Transport/Remap
   * distance'): every interpolation of the level set at the feet of the
   * characteristics smears a thin filament a little, so a transport that
   * interpolates at every step loses more the shorter the steps. Between
   * remaps the level set of step n is instead the one of the last remap m
   * seen through the characteristics of all steps since,
   *   psi^n(x) = psi^m(X_{m+1}(... X_n(x))),
   * each X_j the trace of step j in the velocity that step used (kept here,
   * on the mesh of the remap, which stays unchanged until the next one).
   * The level set is thus interpolated once per remap, however many steps
   * lie between, and the mesh adapts at remaps only. With the gradient
   * augmented level set the gradient follows the chain rule through all the
   * traces. Checkpoints hold the history, so a resumed run goes on alike.
   */
  template <int dim>
  class LevelSetHistory
  {
  public:
    /** @p remap_distance in finest cells; 0: a remap at every step. */
    LevelSetHistory(const double remap_distance);

    /** Whether steps are composed at all (a positive remap distance). */
    bool
    enabled() const
    {
      return remap_distance > 0;
    }

    /**
     * Keep the velocity that the step of length @p tau about to start
     * traces through (the velocity in @p fields now), if there is a base
     * level set to compose with.
     */
    void
    add_step(const TransportedFields<dim> &fields, const double tau);

    /**
     * Replace the level set of @p fields and its @p level_set_gradient
     * (after the advection of the step last added) by the base ones seen
     * through the kept steps; nothing if there is no base yet.
     */
    void
    compose(TransportedFields<dim>     &fields,
            LevelSetGradient<dim>      &level_set_gradient,
            const BoxMeshLocator<dim>  &locator,
            const LevelSetInterpolation interpolation);

    /**
     * Whether the step just taken, which moved the surface by @p cfl
     * finest cells, must be a remap, so that the next step of @p next_cfl
     * cells does not carry the surface further than the remap distance
     * from where the mesh last adapted to it; also once twice as many
     * steps are kept as the remap distance (in cells), which bounds the
     * cost of a step.
     */
    bool
    remap_due(const double cfl, const double next_cfl);

    /**
     * Make the level set of @p fields (on its current mesh) and its
     * @p level_set_gradient the base.
     */
    void
    remap(const TransportedFields<dim> &fields,
          const LevelSetGradient<dim>  &level_set_gradient);

    /** Add @p shift to the base level set as to the current one. */
    void
    shift_base(TransportedFields<dim> &fields, const double shift);

    /** What a checkpoint holds of the history besides its vectors. */
    struct Scalars
    {
      bool                has_base = false;
      double              moved    = 0;
      std::vector<double> taus;
    };

    Scalars
    scalars() const;

    /**
     * The kept vectors (laid out like the fields): the base level set and
     * its gradient, then per step its velocity and velocity gradient.
     */
    std::vector<const typename TransportedFields<dim>::VectorType *>
    vectors() const;

    /**
     * Make a history as @p scalars describe, with vectors laid out like
     * @p fields, and return them in the order of vectors() to be filled
     * (then call restored()).
     */
    std::vector<typename TransportedFields<dim>::VectorType *>
    restore(const Scalars &scalars, const TransportedFields<dim> &fields);

    /** Make the ghost values of the filled vectors consistent. */
    void
    restored();

    /** The surface may move this many finest cells between two remaps. */
    double
    cells_between_remaps() const
    {
      return remap_distance;
    }

  private:
    using VectorType = typename TransportedFields<dim>::VectorType;

    /** A step since the base: its velocity (as the fields) and gradient. */
    struct Step
    {
      VectorType                  velocity;
      std::array<VectorType, dim> velocity_gradient;
      double                      tau;
    };

    const double remap_distance;
    bool         has_base = false;
    VectorType   base_level_set;
    VectorType   base_gradient;
    /** A deque: a vector would copy the steps when it grows, and a copy
     * of a vector loses its ghost values. */
    std::deque<Step> steps;
    /** Finest cells the surface moved since the base. */
    double moved = 0;
  };
} // namespace vefs

#endif
