#include <vefs/transport/liquid_domain.h>
#include <vefs/transport/volume_correction.h>

#include <cmath>
#include <limits>

namespace vefs
{
  namespace
  {
    /**
     * Fills the level set entries of @p weight (owned and ghost) with the
     * weights of ShiftWeight::surface_speed. False if no vertex of a cut cell
     * moves: the weights are then uniform.
     */
    template <int dim>
    bool
    surface_speed_weights(const TransportedFields<dim>                &fields,
                          typename TransportedFields<dim>::VectorType &weight)
    {
      double fastest = 0;
      for (const auto &cell : fields.dof_handler.active_cell_iterators())
        if (!cell->is_artificial() &&
            fields.surface_crosses(fields.vector(), cell))
          for (const unsigned int v : cell->vertex_indices())
            fastest = std::max(fastest, fields.velocity_at(cell, v).norm());
      fastest = Utilities::MPI::max(
        fastest,
        fields.dof_handler.get_triangulation().get_communicator());
      if (!(fastest > 0))
        return false;
      fields.initialize_vector(weight);
      for (const auto &node : fields.nodes())
        weight(node.dofs[TransportedFields<dim>::level_set_component]) =
          std::max(fields.velocity(node).norm() / fastest, min_speed_weight);
      weight.update_ghost_values();
      return true;
    }
  } // namespace

  template <int dim>
  double
  correct_volume(TransportedFields<dim> &fields,
                 const double            target,
                 const ShiftWeight       weighting)
  {
    typename TransportedFields<dim>::VectorType        weight;
    const typename TransportedFields<dim>::VectorType *shift_weight =
      weighting == ShiftWeight::surface_speed &&
          surface_speed_weights(fields, weight)
        ? &weight
        : nullptr;

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
        const SharpVolume measure =
          sharp_liquid_volume(fields, shift, shift_weight);
        const double residual = measure.volume - target;
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

    constexpr unsigned int c = TransportedFields<dim>::level_set_component;
    for (const auto &node : fields.nodes())
      fields.set_level_set(node,
                           fields.level_set(node) +
                             shift *
                               (shift_weight ? weight(node.dofs[c]) : 1.));
    fields.finalize();
    return shift;
  }

#define VEFS_INSTANTIATE(dim)                              \
  template double correct_volume(TransportedFields<dim> &, \
                                 const double,             \
                                 const ShiftWeight);
  VEFS_INSTANTIATE(2)
  VEFS_INSTANTIATE(3)
#undef VEFS_INSTANTIATE
} // namespace vefs
