#ifndef vefs_transport_parameters_h
#define vefs_transport_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <vefs/transport/volume_correction.h>

#include <string>

namespace vefs
{
  /** How the level set is interpolated at the feet of the characteristics. */
  enum class LevelSetInterpolation
  {
    /** By the dimension: TransportParameters::resolve_level_set(). */
    automatic,
    linear,
    gradient_augmented
  };

  /** How the velocity is interpolated at the feet of the characteristics. */
  enum class VelocityInterpolation
  {
    /** By the regime and the band placement: TransportParameters::resolve(). */
    automatic,
    linear,
    cubic,
    limited_cubic
  };

  /** How the stress is interpolated at the feet ('Stress interpolation'). */
  enum class StressInterpolation
  {
    /** As the velocity: TransportParameters::resolve(). */
    automatic,
    linear,
    limited_cubic
  };

  /**
   * How the fields are carried along the characteristics and the surface
   * kept (doc/transport.md): subsection "Transport". Its last two entries
   * make a transport-only scene: a given velocity instead of the flow, and
   * the exact shape at the end.
   */
  struct TransportParameters
  {
    void
    declare(dealii::ParameterHandler &prm);

    LevelSetInterpolation level_set_interpolation =
      LevelSetInterpolation::automatic;
    VelocityInterpolation velocity_interpolation =
      VelocityInterpolation::automatic;
    StressInterpolation stress_interpolation = StressInterpolation::automatic;
    /** Finest cells the surface moves between remaps; 0: every step. */
    double       remap_distance           = 0;
    bool         automatic_remap_distance = true;
    unsigned int redistancing_interval    = 1;
    bool         volume_correction        = true;
    /** How the correction's shift is spread ('Volume correction shift'). */
    ShiftWeight volume_correction_shift = ShiftWeight::uniform;

    std::string prescribed_velocity   = "";
    std::string exact_final_level_set = "";

    /**
     * An 'automatic' level set interpolation becomes gradient augmented in
     * 2D (@p dimension) and for a prescribed velocity, linear for a 3D
     * flow (there it costs more and was no closer to the 3D dam's
     * reference, doc/transport_in_flows.md) and with @p
     * band_in_one_change_set (that placement keeps Q1 fields only).
     * First of the transport's entries: the band placement's automatic
     * value depends on it.
     */
    void
    resolve_level_set(const unsigned int dimension,
                      const bool         band_in_one_change_set);

    /**
     * 'automatic' velocity interpolation becomes cubic for a stiff
     * elastic solid under gravity (@p stiff_solid: the rule of
     * Parameters::resolve_automatic_entries()) unless @p band_in_one_change
     * (that placement keeps Q1 fields only), linear otherwise: linear
     * interpolation damps an elastic wave (doc/bouncing_ball.md, "The
     * interpolation at the feet"). 'automatic' stress interpolation then
     * becomes limited cubic where the velocity is interpolated by (limited)
     * cubic, linear otherwise: an elastic wave carries its energy in both
     * fields. An 'automatic' remap distance becomes 20 in 2D and 14 in 3D
     * (@p dimension) for the gradient augmented level set carried by a
     * prescribed velocity (unless @p band_predicted: that placement adapts
     * the mesh at every step), 0 otherwise (measured: doc/transport.md,
     * "In 3D").
     */
    void
    resolve(const bool         band_predicted,
            const bool         band_in_one_change,
            const bool         stiff_solid,
            const unsigned int dimension);

    /**
     * Finest cells from the surface within which redistancing leaves the
     * level set as transported in @p dimension: twice the remap distance in
     * 2D, none in 3D (doc/transport.md, "In 3D").
     */
    double
    kept_at_redistancing(const unsigned int dimension) const
    {
      return dimension == 2 ? 2 * remap_distance : 0;
    }

    /**
     * Whether the feet read every field by linear interpolation, which
     * 'Band placement = predicted, one change' needs; before resolve() too
     * (an automatic velocity interpolation is then linear, and an automatic
     * stress interpolation follows the velocity's).
     */
    bool
    feet_linear() const;

    /**
     * feet_linear(), and a flow whose surface is traced every step (remap
     * distance 0, automatic for a flow): where that placement may be
     * chosen automatically.
     */
    bool
    feet_linear_without_remap() const;

    /** The stress at the feet by limited cubic (after resolve()). */
    bool
    cubic_stress_interpolation() const;

    /** Transport only: the velocity is given and the flow is not solved. */
    bool
    velocity_is_prescribed() const
    {
      return !prescribed_velocity.empty();
    }
  };
} // namespace vefs

#endif
