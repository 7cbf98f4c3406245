#ifndef vefs_coarsened_detail_h
#define vefs_coarsened_detail_h

#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/la_parallel_vector.h>

#include <limits>
#include <vector>

namespace vefs
{
  using namespace dealii;

  /**
   * The Q1 fields that a mesh change coarsened away, kept for the advection
   * that follows it: for each cell made from a coarsened family, the values
   * of all components at its former children's vertices (a lattice of 3^dim
   * points). With 'Band placement = predicted, one change' the mesh is
   * refined ahead of the surface and coarsened behind it in one change
   * before the advection, and the feet of the characteristics then lie near
   * the old surface, in cells that change coarsened: interpolated in the
   * former child, the fields there are those the advection would have read
   * on the finer mesh, so the single change loses nothing against a change
   * before and one after the advection.
   *
   * Usage: attach() before Triangulation::execute_coarsening_and_refinement(),
   * unpack() after it and after the fields have been transferred (a refined
   * cell that keeps detail gives its children their former values back),
   * update_ghosts() after the last change, lattice() in the advection,
   * clear() after it.
   */
  template <int dim>
  class CoarsenedDetail
  {
  public:
    using VectorType = LinearAlgebra::distributed::Vector<double>;

    /** Points of the lattice of a family's vertices. */
    static constexpr unsigned int n_points = dim == 2 ? 9 : 27;

    /**
     * The lattice point of vertex @p v of child @p child: per direction the
     * child's offset plus the vertex's, in half cells.
     */
    static unsigned int
    lattice_point(const unsigned int child, const unsigned int v)
    {
      unsigned int index = 0, stride = 1;
      for (unsigned int d = 0; d < dim; ++d, stride *= 3)
        index += stride * (((child >> d) & 1) + ((v >> d) & 1));
      return index;
    }

    /**
     * Before a mesh change: cells to be coarsened will pack their children's
     * values of the @p n_components first components of @p fields (Q1, the
     * layout of @p dof_handler), and cells that keep detail from an earlier
     * change pack it again. The mesh's pack callback refers to this object:
     * it must neither move nor be destroyed before unpack().
     */
    void
    attach(parallel::distributed::Triangulation<dim> &mesh,
           const DoFHandler<dim>                     &dof_handler,
           const VectorType                          &fields,
           const unsigned int                         n_components);

    /**
     * After the change and the transfer of @p fields (owned entries set,
     * ghosts stale): keep the packed detail for the new cells; the children
     * of a refined cell that kept detail take its lattice values.
     */
    void
    unpack(parallel::distributed::Triangulation<dim> &mesh,
           const DoFHandler<dim>                     &dof_handler,
           VectorType                                &fields);

    /** Give ghost cells the detail of their owners. Collective. */
    void
    update_ghosts(const parallel::distributed::Triangulation<dim> &mesh);

    /**
     * The lattice values of @p cell (locally owned or ghost), point by
     * point in lattice order (index sum_d a_d 3^d, a_d = 0, 1, 2 the
     * offset in half cells), all components of a point together; nullptr if
     * the cell has no detail.
     */
    const double *
    lattice(const typename Triangulation<dim>::active_cell_iterator &cell) const
    {
      if (offsets.empty())
        return nullptr;
      const unsigned int offset = offsets[cell->active_cell_index()];
      return offset == none ? nullptr : values.data() + offset;
    }

    /**
     * The Q1 values of all components at the unit-cell point @p xi of a
     * cell with detail @p lattice (from lattice()), in the former child
     * that holds the point, added to @p values.
     */
    void
    add_values(const double     *lattice,
               const Point<dim> &xi,
               double           *values) const;

    /** Forget all detail (after the advection has read it). */
    void
    clear();

  private:
    static constexpr unsigned int none =
      std::numeric_limits<unsigned int>::max();

    /** Keep @p lattice (n_points * n_components values) for @p cell. */
    void
    store(const typename Triangulation<dim>::active_cell_iterator &cell,
          const double                                            *lattice);

    unsigned int n_components = 0;
    unsigned int handle       = none;
    /** Per active cell index: where its lattice starts in values, or none. */
    std::vector<unsigned int> offsets;
    std::vector<double>       values;
  };
} // namespace vefs

#endif
