#ifndef vefs_vertex_field_transfer_h
#define vefs_vertex_field_transfer_h

#include <deal.II/distributed/tria.h>

#include <vefs/compat/box_q1_values.h>
#include <vefs/fields/transported_fields.h>

#include <vector>

namespace vefs
{
  using namespace dealii;

  /**
   * Carries chosen components of Q1 vectors with the layout of the fields
   * through a change of the mesh. Each cell packs the values at its vertices
   * only (a cell to be coarsened: at its children's corners), and a refined
   * cell's children take the Q1 interpolant of their parent. deal.II's
   * SolutionTransfer packs every component of every vector for every cell
   * and interpolates with dense matrices of all dofs (80 x 80 for the ten
   * fields in 3D); the level set gradient and the predicted surface use
   * three and one of their ten slots.
   *
   * Usage: construct before Triangulation::execute_coarsening_and_refinement(),
   * call unpack() after TransportedFields::setup_dofs().
   */
  template <int dim>
  class VertexFieldTransfer
  {
  public:
    using VectorType = typename TransportedFields<dim>::VectorType;

    /** The components of one vector to carry. */
    struct Slot
    {
      const VectorType         *vector;
      std::vector<unsigned int> components;
    };

    VertexFieldTransfer(parallel::distributed::Triangulation<dim> &mesh,
                        const TransportedFields<dim>              &fields,
                        const std::vector<Slot>                   &slots);

    /** The mesh's pack callback refers to this object: it must not move. */
    VertexFieldTransfer(const VertexFieldTransfer &) = delete;
    VertexFieldTransfer &
    operator=(const VertexFieldTransfer &) = delete;

    /**
     * Write the carried values into @p vectors, one per slot in the same
     * order, set up with the layout of the new mesh and zero elsewhere
     * (owned entries only: call TransportedFields::finalize() or
     * distribute_constraints() afterwards).
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

    parallel::distributed::Triangulation<dim> &mesh;
    std::vector<Slot>                          slots;
    /** Carried values per vertex: the components of all slots. */
    unsigned int n_values = 0;
    /** The parent's vertices' weights at its children's vertices. */
    const ChildVertexWeights<dim> child_weights;
    unsigned int                  handle;
  };
} // namespace vefs

#endif
