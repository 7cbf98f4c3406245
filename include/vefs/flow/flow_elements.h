#ifndef vefs_flow_elements_h
#define vefs_flow_elements_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <vefs/compat/box_q1_values.h>
#include <vefs/flow/flow_parameters.h>
#include <vefs/transport/liquid_domain.h>

#include <map>
#include <vector>

namespace vefs
{
  /**
   * The elements of the flow's Q1-Q1 space ('Flow/Flow cells').
   * With 'finest' every cell is its own element. With 'parents' the cells
   * of the finest level ('Maximum level') share their parent's element: the
   * flow's velocity and pressure are Q1 on the parents there, one level
   * coarser than the transport, while the liquid domain is still cut out of
   * the finest cells (the seed solved its flow on 5 mm cells over a 1 mm
   * transport grid). The finest cells keep their own degrees of freedom;
   * those at nodes that are not their parent's vertices are interpolated
   * from the parent's: numbered after the flow space's own (FlowNumbering),
   * they are no rows of the matrices and no entries of the Krylov vectors,
   * and after a solve they hold the parent's Q1 interpolant, so that the
   * transport, contact and output read the cells as before.
   *
   * p4est keeps the children of a parent whose children are all active on
   * one rank, so a parent's element lies within one rank's cells. A ghost
   * cell's siblings, though, may be artificial: the ranks exchange the
   * parents' vertex unknowns of ghost cells (exchange_parent_dofs()), and
   * a rank may have to constrain and write into unknowns of such parents
   * that it does not otherwise see (far_parent_dofs()).
   */
  template <int dim>
  class FlowElements
  {
  public:
    using CellIterator = typename Triangulation<dim>::cell_iterator;

    /** @p max_level: the level of the finest cells. */
    FlowElements(const FlowParameters &parameters,
                 const unsigned int    max_level);

    /** Whether the flow's element of @p cell is its parent. */
    bool
    on_parent(const CellIterator &cell) const
    {
      return on_parents && cell->level() == static_cast<int>(finest_level) &&
             cell->level() > 0;
    }

    /** The cell that is the flow's element of @p cell. */
    CellIterator
    element(const CellIterator &cell) const
    {
      return on_parent(cell) ? cell->parent() : cell;
    }

    /** The size h of the flow's element of @p cell (shortest edge). */
    double
    size(const CellIterator &cell) const
    {
      const double h = cell->minimum_vertex_distance();
      return on_parent(cell) ? 2 * h : h;
    }

    /** Whether @p a and @p b lie in the same element. */
    bool
    same_element(const CellIterator &a, const CellIterator &b) const
    {
      return on_parent(a) && on_parent(b) && a->parent() == b->parent();
    }

    using Location = typename LiquidDomain<dim>::Location;

    /**
     * Where the elements of the owned and ghost cells lie with respect to
     * the liquid of @p domain. An element on a parent is full if all its
     * children are, empty if all are, cut otherwise.
     */
    void
    classify(const DoFHandler<dim>   &dof_handler,
             const LiquidDomain<dim> &domain);

    /** Where the element of an owned or ghost @p cell lies (after
     * classify()). */
    Location
    location(
      const typename Triangulation<dim>::active_cell_iterator &cell) const
    {
      return on_parents ? element_locations[cell->active_cell_index()]
                        : domain->location(cell);
    }

    /**
     * Whether the element of an owned or ghost @p cell holds liquid: then
     * the cell carries flow unknowns (with parents: also a dry child of a
     * parent with liquid, whose vertex is one of the element's).
     */
    bool
    has_liquid(
      const typename Triangulation<dim>::active_cell_iterator &cell) const
    {
      return location(cell) != Location::empty;
    }

    /**
     * After the flow unknowns are distributed (active FE index @p fe_index
     * on cells with flow unknowns): receive the unknowns at the parent's
     * vertices of every ghost cell on its parent from the rank that owns
     * it. @p relevant: the locally relevant unknowns.
     */
    void
    exchange_parent_dofs(const DoFHandler<dim> &dof_handler,
                         const unsigned int     fe_index,
                         const IndexSet        &relevant);

    /** Of component @p c at vertex @p v of the parent of the owned or ghost
     * @p cell, which is on its parent (after exchange_parent_dofs()). */
    types::global_dof_index
    parent_vertex_dof(const typename DoFHandler<dim>::cell_iterator &cell,
                      const unsigned int                             v,
                      const unsigned int                             c) const;

    /** The parent vertices' unknowns of ghost cells that are not locally
     * relevant (after exchange_parent_dofs()). */
    const IndexSet &
    far_parent_dofs() const
    {
      return far_dofs;
    }

    /**
     * The flow unknowns of owned and ghost cells on their parent (active FE
     * index @p fe_index) at nodes that are not vertices of the parent: those
     * make_interpolation_constraints() constrains. Of the size of
     * @p dof_handler's unknowns.
     */
    IndexSet
    interpolated_dofs(const DoFHandler<dim> &dof_handler,
                      const unsigned int     fe_index) const;

    /**
     * Into @p constraints: every flow unknown of a cell on its parent at a
     * node that is not a vertex of the parent equals the parent's Q1
     * interpolant, in every component. Owned and ghost cells with flow
     * unknowns (active FE index @p fe_index; after exchange_parent_dofs()).
     * Unknowns already constrained are left alone.
     */
    void
    make_interpolation_constraints(
      const DoFHandler<dim>     &dof_handler,
      const unsigned int         fe_index,
      AffineConstraints<double> &constraints) const;

    /**
     * Whether the owned @p cell, on its parent, is the first owned child of
     * that parent: the one through which a loop over the owned cells visits
     * the parent's element once.
     */
    bool
    represents_family(const CellIterator &cell) const
    {
      const auto parent = cell->parent();
      for (unsigned int c = 0; c < parent->n_children(); ++c)
        if (parent->child(c)->is_locally_owned())
          return parent->child(c) == cell;
      return false;
    }

    /**
     * Add the cell matrix @p fine of a cell on its parent, child @p child,
     * to @p parent, in the unknowns of the parent's vertices: P^T fine P
     * with P the Q1 interpolation from the parent's vertices to the
     * child's, component by component (the cell's FE @p fe: Q1 in every
     * component; @p parent of its size). The assembly sums a family so and
     * adds the sum with the parent's unknowns (parent_vertex_dof()) once,
     * instead of expanding the interpolation constraints of every entry.
     */
    void
    add_restricted_to_parent(const FiniteElement<dim> &fe,
                             const unsigned int        child,
                             const FullMatrix<double> &fine,
                             FullMatrix<double>       &parent) const;

    /**
     * The same for a cell matrix that is zero outside the rows and columns
     * of the @p components: only those are restricted (the Schur
     * preconditioner's cell matrix holds the pressure only).
     */
    void
    add_restricted_to_parent(const FiniteElement<dim>        &fe,
                             const unsigned int               child,
                             const FullMatrix<double>        &fine,
                             FullMatrix<double>              &parent,
                             const std::vector<unsigned int> &components) const;

    /** The same for a cell vector: P^T fine. */
    void
    add_restricted_to_parent(const FiniteElement<dim> &fe,
                             const unsigned int        child,
                             const Vector<double>     &fine,
                             Vector<double>           &parent) const;

    /** The non-zero weights (vertex, weight) of the parent's vertices at
     * vertex @p v of child @p child. */
    const std::vector<std::pair<unsigned int, double>> &
    vertex_weights(const unsigned int child, const unsigned int v) const
    {
      return child_vertex_weights[child][v];
    }

  private:
    /**
     * @p function(cell, v, weights) for every vertex v that is not a vertex
     * of the parent, of every owned or ghost cell on its parent with active
     * FE index @p fe_index; weights: vertex_weights() there.
     */
    template <typename VertexFunction>
    void
    for_each_interpolated_vertex(const DoFHandler<dim> &dof_handler,
                                 const unsigned int     fe_index,
                                 const VertexFunction  &function) const;

    /** The non-zero weights (vertex, weight) of the parent's vertices at
     * vertex v of child c: [c][v]. */
    const ChildVertexWeights<dim> child_vertex_weights;

    const bool         on_parents;
    const unsigned int finest_level;
    /** 0, ..., dim: the components of the flow. */
    std::vector<unsigned int> all_components;
    /** Reused by add_restricted_to_parent(): it runs for every child. */
    mutable FullMatrix<double>        restriction_scratch;
    mutable std::vector<unsigned int> restriction_rows;
    const LiquidDomain<dim>          *domain = nullptr;
    /** With parents: by active cell index, of owned and ghost cells. */
    std::vector<Location> element_locations;
    /** Unknowns at the parent's vertices, (vertex, component) in
     * lexicographic order, of ghost cells on their parent, by active cell
     * index. */
    std::map<unsigned int, std::vector<types::global_dof_index>>
             ghost_parent_dofs;
    IndexSet far_dofs;
  };
} // namespace vefs

#endif
