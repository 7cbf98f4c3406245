#ifndef vefs_componentwise_constraints_h
#define vefs_componentwise_constraints_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>

#include <vector>

namespace vefs
{
  using namespace dealii;

  /**
   * DoFTools::make_hanging_node_constraints() and, for each direction d of
   * @p periodic_directions, make_periodicity_constraints() between the walls
   * 2d and 2d + 1, for @p dof_handler of FE_Q(1)^n whose vertices number
   * their n components consecutively: computed once for a scalar FE_Q(1)
   * and repeated for every component. deal.II's builds every hanging face's
   * constraints from the element's face matrix, n x 2n entries in 2D: with
   * the dumbbells' hundreds of components that took 86 % of a step
   * (doc/dumbbells.md). @p constraints is reinit() with the locally relevant
   * degrees of freedom of @p dof_handler, filled and closed.
   */
  template <int dim>
  void
  make_componentwise_constraints(
    const DoFHandler<dim>           &dof_handler,
    const std::vector<unsigned int> &periodic_directions,
    const IndexSet                  &relevant_dofs,
    AffineConstraints<double>       &constraints);
} // namespace vefs

#endif
