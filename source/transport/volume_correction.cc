#include <vefs/transport/liquid_domain.h>
#include <vefs/transport/volume_correction.h>

#include <cmath>
#include <limits>

namespace vefs
{
  template <int dim>
  double
  correct_volume(TransportedFields<dim> &fields, const double target)
  {
    // Newton's method on the shift, for the sharp volume the flow step sees.
    // From a residual below 1e-10 the next one is below round-off: that step
    // is taken without measuring again (from 1e-7 it was not: the vortex
    // from a distance kept its volume to 1.1e-9 only, doc/transport.md).
    // The volume falls with the shift; where it is steep between flat parts
    // (a level set nearly constant over cells) Newton alternates across the
    // root, so once the shifts measured bracket it, a Newton step that
    // leaves the bracket is replaced by bisection (doc/time_step_surface.md,
    // step 4).
    double shift = 0;
    double below = -std::numeric_limits<double>::infinity(); // volume > target
    double above = std::numeric_limits<double>::infinity();  // volume < target
    double best_shift = 0, best_residual = std::numeric_limits<double>::max();
    for (unsigned int iteration = 0; iteration < 60; ++iteration)
      {
        const SharpVolume measure  = sharp_liquid_volume(fields, shift);
        const double      residual = measure.volume - target;
        if (std::abs(residual) < best_residual)
          {
            best_residual = std::abs(residual);
            best_shift    = shift;
          }
        if (std::abs(residual) <= 1e-14 * target)
          break;
        (residual > 0 ? below : above) = shift;
        const bool bracketed = std::isfinite(below) && std::isfinite(above);
        // Where the measured volume jumps, no shift hits the target: the
        // bracket closes on the jump and the closer side is kept.
        if (bracketed &&
            above - below <= 4 * std::numeric_limits<double>::epsilon() *
                               std::max(std::abs(below), std::abs(above)))
          break;
        const double newton = measure.derivative != 0
                                ? shift - residual / measure.derivative
                                : shift;
        const bool   newton_in_bracket =
          measure.derivative != 0 &&
          (!bracketed || (below < newton && newton < above));
        if (!newton_in_bracket && !bracketed)
          break;
        shift = newton_in_bracket ? newton : 0.5 * (below + above);
        if (newton_in_bracket && std::abs(residual) <= 1e-10 * target)
          {
            best_shift = shift;
            break;
          }
      }
    shift = best_shift;

    for (const auto &node : fields.nodes())
      fields.set_level_set(node, fields.level_set(node) + shift);
    fields.finalize();
    return shift;
  }

#define VEFS_INSTANTIATE(dim) \
  template double correct_volume(TransportedFields<dim> &, const double);
  VEFS_INSTANTIATE(2)
  VEFS_INSTANTIATE(3)
#undef VEFS_INSTANTIATE
} // namespace vefs
