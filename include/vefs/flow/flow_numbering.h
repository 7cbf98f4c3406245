#ifndef vefs_flow_numbering_h
#define vefs_flow_numbering_h

#include <deal.II/base/index_set.h>
#include <deal.II/dofs/dof_handler.h>

#include <vefs/flow/flow_elements.h>

#include <array>
#include <vector>

namespace vefs
{
  using namespace dealii;

  /**
   * The numbering of the flow's degrees of freedom in four parts: the flow
   * space's own velocities and pressures first, then the velocities and
   * pressures that are interpolated from them (with 'Flow cells = parents',
   * the unknowns of the finest cells at nodes that are not vertices of their
   * parent, FlowElements). The matrices, the Krylov vectors and the
   * preconditioners hold the first two parts only; the solution is
   * interpolated into the last two after each solve, for the transport,
   * the output and the contact reactions, which read it cell by cell.
   */
  struct FlowNumbering
  {
    /** Number of dofs of each part: velocities, pressures, interpolated
     * velocities, interpolated pressures. */
    std::array<types::global_dof_index, 4> n_dofs_of_part = {};

    /** The first index of @p part. */
    types::global_dof_index
    start(const unsigned int part) const
    {
      types::global_dof_index first = 0;
      for (unsigned int p = 0; p < part; ++p)
        first += n_dofs_of_part[p];
      return first;
    }

    /** The flow space's own velocities. */
    types::global_dof_index
    n_velocities() const
    {
      return n_dofs_of_part[0];
    }

    /** The flow space's own unknowns: those of the matrices. */
    types::global_dof_index
    n_flow_dofs() const
    {
      return start(2);
    }

    /**
     * @p set (indices of all dofs) split into the blocks of the flow
     * system, velocities and pressures, each numbered within its block.
     */
    std::vector<IndexSet>
    flow_blocks(const IndexSet &set) const;

    /** @p set split into the four parts, each numbered within its part;
     * the first two only if there are no interpolated dofs (a block of
     * size 0 breaks deal.II 9.4's DataOut). */
    std::vector<IndexSet>
    all_parts(const IndexSet &set) const;
  };

  /**
   * Renumber the dofs of @p dof_handler, the flow's Q1 velocity and
   * pressure on the cells of active FE index @p fe_index, into the four
   * parts of FlowNumbering, the interpolated ones those of
   * FlowElements::interpolated_dofs(). Within a part the dofs keep their
   * order (by rank, then by index); without interpolated dofs the numbering
   * is deal.II's component-wise one (velocities, then pressures). Collective.
   */
  template <int dim>
  FlowNumbering
  renumber_flow_dofs(DoFHandler<dim>         &dof_handler,
                     const FlowElements<dim> &elements,
                     const unsigned int       fe_index);
} // namespace vefs

#endif
