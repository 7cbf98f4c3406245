#ifndef vefs_vertex_hanging_nodes_h
#define vefs_vertex_hanging_nodes_h

#include <deal.II/base/index_set.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>

namespace vefs
{
  using namespace dealii;

  /**
   * The hanging node constraints of FE_Q(1)^n on a mesh of isotropically
   * refined boxes (p4est's): the vertex in the middle of a refined edge of an
   * active cell is the mean of the edge's two vertices and, in 3D, the vertex
   * in the middle of a refined face the mean of its four, in each component
   * alike. The same constraints as DoFTools::make_hanging_node_constraints(),
   * which derives them from the element's face interpolation for each face
   * and each of the n components: that took 1.5 % of a run of the 3D ball at
   * 2.5 mm, once per mesh change. Constrains the @p relevant_dofs only,
   * from the cells that are not artificial.
   */
  template <int dim>
  void
  make_vertex_hanging_node_constraints(const DoFHandler<dim>     &dof_handler,
                                       const IndexSet            &relevant_dofs,
                                       AffineConstraints<double> &constraints);
} // namespace vefs

#endif
