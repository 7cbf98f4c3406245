#ifndef vefs_volume_correction_h
#define vefs_volume_correction_h

#include <vefs/fields/transported_fields.h>

namespace vefs
{
  /**
   * Restore the liquid volume @p target, as the flow step measures it
   * (sharp_liquid_volume()), by adding one constant to psi,
   * i.e. by moving the whole free surface along its normal by the same
   * small distance. Returns that distance.
   */
  template <int dim>
  double
  correct_volume(TransportedFields<dim> &fields, const double target);

} // namespace vefs

#endif
