#ifndef vefs_nodal_gradients_h
#define vefs_nodal_gradients_h

#include <vefs/fields/transported_fields.h>

#include <array>

namespace vefs
{
  /**
   * Gradients of the first @p n_components fields at the nodes, recovered by
   * averaging the gradients of the cells' Q1 interpolants over the cells
   * around a node (central differences on a uniform mesh: second order,
   * where the Q1 gradient inside a cell is first order). Entry j of the
   * result holds d f_c / dx_j at the degree of freedom of component c
   * (ghosted).
   */
  template <int dim>
  std::array<typename TransportedFields<dim>::VectorType, dim>
  recover_nodal_gradients(const TransportedFields<dim> &fields,
                          const unsigned int            n_components);
} // namespace vefs

#endif
