#ifndef vefs_field_extension_h
#define vefs_field_extension_h

#include <vefs/transported_fields.h>

namespace vefs
{
  /**
   * Extend the flow fields (the velocity, and the stress if there is one)
   * from the nodes flagged in @p known (the nodes of liquid cells, flag = 1
   * in the first component of the node) into @p n_layers layers of cells
   * around the liquid: each layer gives an unknown node the average of the
   * known nodes of the cells it shares with them. The characteristics of the
   * next step trace back through this band; farther nodes get zero.
   */
  template <int dim>
  void
  extend_flow_fields(TransportedFields<dim>                      &fields,
                     typename TransportedFields<dim>::VectorType &known,
                     const unsigned int                           n_layers);
} // namespace vefs

#endif
