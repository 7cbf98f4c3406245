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

#include <algorithm>
#include <map>
#include <vector>

namespace vefs
{
  /**
   * The elements of the flow's Q1-Q1 space ('Flow/Flow cells'), k levels
   * coarser than the finest cells ('Maximum level'): with k = 0 ('finest')
   * every cell is its own element; with k > 0 ('parents' 1, 'grandparents'
   * 2) every cell finer than the flow level (the finest level minus k)
   * shares the element of its ancestor on the flow level. The flow's velocity
   * and pressure are Q1 on that ancestor while the liquid domain is still cut
   * out of the finest cells (the seed solved its flow on 5 mm cells over a 1 mm
   * transport grid). The cells keep their own degrees of freedom; those at
   * nodes that are not vertices of their element are interpolated from the
   * element's: numbered after the flow space's own (FlowNumbering), they
   * are no rows of the matrices and no entries of the Krylov vectors, and
   * after a solve they hold the element's Q1 interpolant, so that the
   * transport, contact and output read the cells as before.
   *
   * With 'Finest cells at contact walls' the elements on the flow level
   * that touch a contact wall keep their cells as elements of their own:
   * the contact set then lives on the finest cells' wall nodes, as with
   * k = 0 (on a coarser element's wall vertices it stops a body while the
   * liquid is still an element above the wall). Their nodes on the faces
   * of coarser elements are interpolated from those, but stay the flow
   * space's unknowns, as hanging nodes do.
   *
   * An element's cells lie on one rank (with k = 1 p4est keeps a family of
   * active children together). A ghost cell's element may reach into
   * artificial cells, though: the ranks exchange the element's vertex
   * unknowns of ghost cells (exchange_element_dofs()), and a rank may have
   * to constrain and write into unknowns of such elements that it does not
   * otherwise see (far_element_dofs()).
   */
  template <int dim>
  class FlowElements
  {
  public:
    using CellIterator = typename Triangulation<dim>::cell_iterator;
    using ActiveCellIterator =
      typename Triangulation<dim>::active_cell_iterator;

    /**
     * @p max_level: the level of the finest cells. Along the walls
     * @p finest_walls (boundary ids) the cells are their own elements.
     */
    FlowElements(const FlowParameters                  &parameters,
                 const unsigned int                     max_level,
                 const std::vector<types::boundary_id> &finest_walls = {});

    /**
     * Whether the flow's element of @p cell is a coarser ancestor: @p cell
     * is finer than the flow level, and its ancestor on the flow level
     * touches none of the finest walls.
     */
    bool
    on_coarser_element(const CellIterator &cell) const
    {
      return cell->level() > flow_level &&
             !touches_finest_wall(flow_level_ancestor(cell));
    }

    /** The cell that is the flow's element of @p cell (an iterator of
     * @p cell's kind: of the Triangulation or the DoFHandler). */
    template <typename Accessor>
    TriaIterator<Accessor>
    element(const TriaIterator<Accessor> &cell) const
    {
      const TriaIterator<Accessor> ancestor = flow_level_ancestor(cell);
      return touches_finest_wall(ancestor) ? cell : ancestor;
    }

    /** The size h of the flow's element of @p cell (shortest edge). */
    double
    size(const CellIterator &cell) const
    {
      const double h = cell->minimum_vertex_distance();
      return on_coarser_element(cell) ? h * (1u << (cell->level() - flow_level))
                                      : h;
    }

    /** Whether @p a and @p b lie in the same element. */
    bool
    same_element(const CellIterator &a, const CellIterator &b) const
    {
      return on_coarser_element(a) && on_coarser_element(b) &&
             element(a) == element(b);
    }

    /** The active cells of @p element, depth first in deal.II's child
     * order (iterators of @p element's kind). */
    template <typename Accessor>
    std::vector<TriaActiveIterator<Accessor>>
    cells_of(const TriaIterator<Accessor> &element) const
    {
      std::vector<TriaActiveIterator<Accessor>> cells;
      std::vector<TriaIterator<Accessor>>       pending = {element};
      while (!pending.empty())
        {
          const TriaIterator<Accessor> cell = pending.back();
          pending.pop_back();
          if (cell->is_active())
            cells.emplace_back(cell);
          else
            for (unsigned int c = cell->n_children(); c-- > 0;)
              pending.push_back(cell->child(c));
        }
      return cells;
    }

    using Location = typename LiquidDomain<dim>::Location;

    /**
     * Where the elements of the owned and ghost cells lie with respect to
     * the liquid of @p domain. A coarser element is full if all its cells
     * are, empty if all are, cut otherwise.
     */
    void
    classify(const DoFHandler<dim>   &dof_handler,
             const LiquidDomain<dim> &domain);

    /** Where the element of an owned or ghost @p cell lies (after
     * classify()). */
    Location
    location(const ActiveCellIterator &cell) const
    {
      return level_offset > 0 ? element_locations[cell->active_cell_index()]
                              : domain->location(cell);
    }

    /**
     * Whether the element of an owned or ghost @p cell holds liquid: then
     * the cell carries flow unknowns (on a coarser element: also a dry cell
     * of an element with liquid, whose vertex may be one of the element's).
     */
    bool
    has_liquid(const ActiveCellIterator &cell) const
    {
      return location(cell) != Location::empty;
    }

    /**
     * After the flow unknowns are distributed (active FE index @p fe_index
     * on cells with flow unknowns): receive the unknowns at the element's
     * vertices of every ghost cell on a coarser element from the rank that
     * owns it. @p relevant: the locally relevant unknowns.
     */
    void
    exchange_element_dofs(const DoFHandler<dim> &dof_handler,
                          const unsigned int     fe_index,
                          const IndexSet        &relevant);

    /** Of component @p c at vertex @p v of the element of the owned or
     * ghost @p cell, which is on a coarser element (after
     * exchange_element_dofs()). */
    types::global_dof_index
    element_vertex_dof(const typename DoFHandler<dim>::cell_iterator &cell,
                       const unsigned int                             v,
                       const unsigned int                             c) const;

    /** The element vertices' unknowns of ghost cells that are not locally
     * relevant (after exchange_element_dofs()). */
    const IndexSet &
    far_element_dofs() const
    {
      return far_dofs;
    }

    /**
     * The flow unknowns of owned and ghost cells on a coarser element
     * (active FE index @p fe_index) at nodes that are not vertices of the
     * element: those make_interpolation_constraints() constrains. Of the
     * size of @p dof_handler's unknowns.
     */
    IndexSet
    interpolated_dofs(const DoFHandler<dim> &dof_handler,
                      const unsigned int     fe_index) const;

    /**
     * Into @p constraints: every flow unknown of a cell on a coarser element
     * at a node that is not a vertex of the element equals the element's Q1
     * interpolant, in every component. Owned and ghost cells with flow
     * unknowns (active FE index @p fe_index; after exchange_element_dofs()).
     * Unknowns already constrained are left alone.
     */
    void
    make_interpolation_constraints(
      const DoFHandler<dim>     &dof_handler,
      const unsigned int         fe_index,
      AffineConstraints<double> &constraints) const;

    /**
     * Whether the owned @p cell, on a coarser element, is the element's
     * first cell (cells_of(); all are owned): the one through which a loop
     * over the owned cells visits the element once.
     */
    bool
    represents_element(const CellIterator &cell) const
    {
      return corner_cell(cell, 0) == cell;
    }

    /**
     * Add the cell matrix @p fine of the active @p cell, on a coarser
     * element, to @p coarse, in the unknowns of the element's vertices: P^T
     * fine P with P the Q1 interpolation from the element's vertices to the
     * cell's, component by component (the cell's FE @p fe: Q1 in every
     * component; @p coarse of its size). The assembly sums an element's
     * cells so and adds the sum with the element's unknowns
     * (element_vertex_dof()) once, instead of expanding the interpolation
     * constraints of every entry.
     */
    void
    add_restricted_to_element(const FiniteElement<dim> &fe,
                              const CellIterator       &cell,
                              const FullMatrix<double> &fine,
                              FullMatrix<double>       &coarse) const;

    /**
     * The same for a cell matrix that is zero outside the rows and columns
     * of the @p components: only those are restricted (the Schur
     * preconditioner's cell matrix holds the pressure only).
     */
    void
    add_restricted_to_element(
      const FiniteElement<dim>        &fe,
      const CellIterator              &cell,
      const FullMatrix<double>        &fine,
      FullMatrix<double>              &coarse,
      const std::vector<unsigned int> &components) const;

    /** The same for a cell vector: P^T fine. */
    void
    add_restricted_to_element(const FiniteElement<dim> &fe,
                              const CellIterator       &cell,
                              const Vector<double>     &fine,
                              Vector<double>           &coarse) const;

    /** The non-zero weights (vertex, weight) of the element's vertices at
     * each vertex of @p cell, which is on a coarser element: [v]. */
    using CellWeights =
      std::vector<std::vector<std::pair<unsigned int, double>>>;
    const CellWeights &
    weights_of(const CellIterator &cell) const;

    /** The same at vertex @p v of @p cell. */
    const std::vector<std::pair<unsigned int, double>> &
    vertex_weights(const CellIterator &cell, const unsigned int v) const
    {
      return weights_of(cell)[v];
    }

  private:
    /**
     * @p function(cell, v, weights) for every vertex v that is not a vertex
     * of the element, of every owned or ghost cell on a coarser element with
     * active FE index @p fe_index; weights: vertex_weights() there.
     */
    template <typename VertexFunction>
    void
    for_each_interpolated_vertex(const DoFHandler<dim> &dof_handler,
                                 const unsigned int     fe_index,
                                 const VertexFunction  &function) const;

    /** The active cell of the element of @p cell that holds the element's
     * vertex @p v (an iterator of @p cell's kind). */
    template <typename Iterator>
    Iterator
    corner_cell(const Iterator &cell, const unsigned int v) const
    {
      Iterator corner = cell;
      while (corner->level() > flow_level)
        corner = corner->parent();
      // Child v of a cell holds the cell's vertex v.
      while (corner->has_children())
        corner = corner->child(v);
      return corner;
    }

    /** @p cell's ancestor on the flow level, or @p cell if not finer. */
    template <typename Accessor>
    TriaIterator<Accessor>
    flow_level_ancestor(const TriaIterator<Accessor> &cell) const
    {
      TriaIterator<Accessor> ancestor = cell;
      while (ancestor->level() > flow_level)
        ancestor = ancestor->parent();
      return ancestor;
    }

    /** Whether @p cell lies at one of the finest walls. */
    bool
    touches_finest_wall(const CellIterator &cell) const
    {
      if (finest_walls.empty())
        return false;
      for (const unsigned int f : cell->face_indices())
        if (cell->at_boundary(f) &&
            std::find(finest_walls.begin(),
                      finest_walls.end(),
                      cell->face(f)->boundary_id()) != finest_walls.end())
          return true;
      return false;
    }

    const unsigned int level_offset;
    /** The level of the coarser elements: the finest level minus k. */
    const int flow_level;
    /**
     * Boundary ids of the walls along which the cells stay their own
     * elements (the contact walls with 'Finest cells at contact walls':
     * doc/time_step_flow.md, "Flow on coarser cells").
     */
    const std::vector<types::boundary_id> finest_walls;
    /**
     * The non-zero weights (vertex, weight) of an element's vertices at the
     * vertices of its cells k' = 1..k levels finer: [k' - 1][position][v],
     * position the cell's place in the element's 2^k' lattice
     * (lexicographic, x fastest).
     */
    std::vector<ChildVertexWeights<dim>> descendant_vertex_weights;
    /** 0, ..., dim: the components of the flow. */
    std::vector<unsigned int> all_components;
    /** Reused by add_restricted_to_element(): it runs for every cell. */
    mutable FullMatrix<double>        restriction_scratch;
    mutable std::vector<unsigned int> restriction_rows;
    const LiquidDomain<dim>          *domain = nullptr;
    /** On coarser elements: by active cell index, of owned and ghost
     * cells. */
    std::vector<Location> element_locations;
    /** Unknowns at the element's vertices, (vertex, component) in
     * lexicographic order, of ghost cells on a coarser element, by active
     * cell index. */
    std::map<unsigned int, std::vector<types::global_dof_index>>
             ghost_element_dofs;
    IndexSet far_dofs;
  };
} // namespace vefs

#endif
