#ifndef vefs_vertex_field_transfer_h
#define vefs_vertex_field_transfer_h

#include <deal.II/distributed/tria.h>

#include <vefs/compat/box_q1_values.h>
#include <vefs/fields/family_lattice.h>
#include <vefs/fields/transported_fields.h>

#include <functional>
#include <utility>
#include <vector>

namespace vefs
{
  using namespace dealii;

  /**
   * Carries vectors with the layout of the fields through a change of the
   * mesh: the one transfer of vertex data in vefs (doc/code.md, "The
   * fields").
   *
   * Vertex values: chosen components of chosen vectors (slots). Each cell
   * packs the values at its vertices only (a cell to be coarsened: at its
   * children's corners), and a refined cell's children take the Q1
   * interpolant of their parent. deal.II's SolutionTransfer packs every
   * component of every vector for every cell and interpolates with dense
   * matrices of all dofs (80 x 80 for the ten fields in 3D); the level set
   * gradient and the predicted surface use three and one of their ten
   * slots.
   *
   * Lattice values, if a LatticeSource is given: values at the vertices of
   * a family's children (FamilyLattice), which a refined cell's children
   * take instead of the Q1 interpolant (the cubic level set, a detail kept
   * from an earlier change), and which a coarsened cell or one that keeps
   * detail hands back to the source after the change.
   *
   * Usage: construct before Triangulation::execute_coarsening_and_refinement(),
   * call unpack() after TransportedFields::setup_dofs().
   */
  template <int dim>
  class VertexFieldTransfer
  {
  public:
    using VectorType = typename TransportedFields<dim>::VectorType;

    using CellStatus = typename Triangulation<dim>::CellStatus;

    /** The components of one vector to carry. */
    struct Slot
    {
      const VectorType         *vector;
      std::vector<unsigned int> components;
    };

    /** Where the lattice values of the cells come from and go to. */
    class LatticeSource
    {
    public:
      virtual ~LatticeSource() = default;

      /**
       * The (slot, component) of each value at a lattice point, the slots
       * numbered as those of the transfer.
       */
      virtual std::vector<std::pair<unsigned int, unsigned int>>
      components() const = 0;

      /**
       * What @p cell, about to change as @p status says, carries: the
       * values at the lattice points, point by point, all components of a
       * point together; empty for nothing. For a cell to be refined, the
       * values its children's vertices take.
       */
      virtual std::vector<double>
      pack(const typename Triangulation<dim>::cell_iterator &cell,
           const CellStatus                                  status) const = 0;

      /** Before the first keep() of a change. */
      virtual void
      start_keeping(const Triangulation<dim> &)
      {
      }

      /**
       * After the change: the lattice that @p cell (coarsened, or unchanged)
       * packed.
       */
      virtual void
      keep(const typename Triangulation<dim>::active_cell_iterator &,
           const double *)
      {
        AssertThrow(false, ExcInternalError());
      }
    };

    /**
     * @p lattice_source, if given, must live until unpack() and take the
     * slots of its components() from @p slots.
     */
    VertexFieldTransfer(parallel::distributed::Triangulation<dim> &mesh,
                        const TransportedFields<dim>              &fields,
                        const std::vector<Slot>                   &slots,
                        LatticeSource *lattice_source = nullptr);

    /** The mesh's pack callback refers to this object: it must not move. */
    VertexFieldTransfer(const VertexFieldTransfer &) = delete;
    VertexFieldTransfer &
    operator=(const VertexFieldTransfer &) = delete;

    /**
     * Write the carried values into @p vectors, one per slot in the same
     * order, set up with the layout of the new mesh and zero elsewhere
     * (owned entries only: call TransportedFields::finalize() or
     * distribute_constraints() afterwards): the vertex values first, then
     * the lattice values over them, cell by cell.
     */
    void
    unpack(const TransportedFields<dim>    &fields,
           const std::vector<VectorType *> &vectors);

  private:
    /**
     * The carried values at the vertices of @p cell, vertex by vertex, as
     * the bytes of the transfer.
     */
    std::vector<char>
    vertex_values(const TransportedFields<dim>                     &fields,
                  const typename Triangulation<dim>::cell_iterator &cell,
                  const bool from_children) const;

    void
    write(const TransportedFields<dim>                            &fields,
          const typename Triangulation<dim>::active_cell_iterator &cell,
          const double                                            *values,
          const std::vector<VectorType *> &vectors) const;

    /** The lattice values of a refined @p parent into its children. */
    void
    write_lattice(const TransportedFields<dim>                     &fields,
                  const typename Triangulation<dim>::cell_iterator &parent,
                  const double                                     *lattice,
                  const std::vector<VectorType *> &vectors) const;

    parallel::distributed::Triangulation<dim> &mesh;
    std::vector<Slot>                          slots;
    /** Carried values per vertex: the components of all slots. */
    unsigned int n_values = 0;
    /** The parent's vertices' weights at its children's vertices. */
    const ChildVertexWeights<dim> child_weights;
    unsigned int                  handle;
    LatticeSource                *lattice_source;
    /** The (slot, component) of each lattice value at a point. */
    std::vector<std::pair<unsigned int, unsigned int>> lattice_components;
    unsigned int                                       lattice_handle = 0;
  };

  /**
   * The vectors of @p slots carried through @p change, a change of @p mesh
   * (refinement, repartition): a VertexFieldTransfer around it and
   * TransportedFields::setup_dofs() after it. One new vector per slot, in
   * their order, laid out like the new fields; owned entries only (swap
   * them in, then finalize).
   */
  template <int dim>
  std::vector<typename TransportedFields<dim>::VectorType>
  carry_through_mesh_change(
    parallel::distributed::Triangulation<dim>                  &mesh,
    TransportedFields<dim>                                     &fields,
    const std::vector<typename VertexFieldTransfer<dim>::Slot> &slots,
    const std::function<void()>                                &change,
    typename VertexFieldTransfer<dim>::LatticeSource *lattice_source = nullptr);
} // namespace vefs

#endif
