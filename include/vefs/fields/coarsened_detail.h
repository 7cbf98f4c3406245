#ifndef vefs_coarsened_detail_h
#define vefs_coarsened_detail_h

#include <deal.II/distributed/tria.h>
#include <deal.II/lac/la_parallel_vector.h>

#include <vefs/fields/family_lattice.h>
#include <vefs/fields/transported_fields.h>
#include <vefs/fields/vertex_field_transfer.h>

#include <limits>
#include <utility>
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
   * Usage: as the LatticeSource of the VertexFieldTransfer of each mesh
   * change (from_fields() before it; the fields are the transfer's slot 0):
   * cells to be coarsened pack their children's values, cells that keep
   * detail from an earlier change pack it again, and a refined cell that
   * kept detail gives its children their former values back.
   * update_ghosts() after the last change, lattice() in the advection,
   * clear() after it.
   */
  template <int dim>
  class CoarsenedDetail : public VertexFieldTransfer<dim>::LatticeSource
  {
  public:
    using VectorType = LinearAlgebra::distributed::Vector<double>;
    using CellStatus = typename Triangulation<dim>::CellStatus;

    /** Points of the lattice of a family's vertices. */
    static constexpr unsigned int n_points = FamilyLattice<dim>::n_points;

    /** The next change packs the detail of @p fields (all components). */
    void
    from_fields(const TransportedFields<dim> &fields);

    std::vector<std::pair<unsigned int, unsigned int>>
    components() const override;

    std::vector<double>
    pack(const typename Triangulation<dim>::cell_iterator &cell,
         const CellStatus status) const override;

    /** Forget the detail of the old mesh; keep() fills it anew. */
    void
    start_keeping(const Triangulation<dim> &mesh) override;

    void
    keep(const typename Triangulation<dim>::active_cell_iterator &cell,
         const double *lattice) override;

    /** Give ghost cells the detail of their owners. Collective. */
    void
    update_ghosts(const parallel::distributed::Triangulation<dim> &mesh);

    /**
     * The lattice values of @p cell (locally owned or ghost), point by
     * point in the order of FamilyLattice, all components of a point
     * together; nullptr if the cell has no detail.
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

    /** The fields whose detail the next change packs (from_fields()). */
    const TransportedFields<dim> *fields       = nullptr;
    unsigned int                  n_components = 0;
    /** Per active cell index: where its lattice starts in values, or none. */
    std::vector<unsigned int> offsets;
    std::vector<double>       values;
  };
} // namespace vefs

#endif
