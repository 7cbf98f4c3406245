#ifndef vefs_volume_correction_h
#define vefs_volume_correction_h

#include <vefs/fields/transported_fields.h>

namespace vefs
{
  /** How the volume correction distributes its shift over the surface. */
  enum class ShiftWeight
  {
    /** The whole surface moves along its normal by the same distance. */
    uniform,
    /**
     * Each node of the level set moves in proportion to its speed |u| over
     * the largest speed at the vertices of cut cells, at least
     * min_speed_weight: the characteristics of a node at rest end at the
     * node itself, and its interpolation there makes no volume error (a
     * falling drop keeps its own area; but a pool at rest whose surface lies
     * on mesh nodes then moves, doc/volume_correction.md). Uniform where no
     * vertex of a cut cell moves.
     */
    surface_speed
  };

  /** The smallest weight of ShiftWeight::surface_speed, so that a volume
   * error made at rest (the measure of refined cut cells) can still be
   * corrected (doc/time_step_surface.md, step 4). */
  inline constexpr double min_speed_weight = 0.05;

  /**
   * Restore the liquid volume @p target, as the flow step measures it
   * (sharp_liquid_volume()), by adding c w to psi, w the nodal weights of
   * @p weighting: c by Newton's method on the volume. Returns c, with
   * ShiftWeight::uniform the distance the surface moved along its normal.
   */
  template <int dim>
  double
  correct_volume(TransportedFields<dim> &fields,
                 const double            target,
                 const ShiftWeight       weighting = ShiftWeight::uniform);
} // namespace vefs

#endif
