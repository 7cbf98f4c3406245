#ifndef vefs_transported_fields_h
#define vefs_transported_fields_h

#include <deal.II/base/index_set.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/la_parallel_vector.h>

#include <array>
#include <vector>

namespace vefs
{
  using namespace dealii;

  /**
   * The fields carried along the characteristics, as continuous Q1 fields on
   * the whole cavity: the velocity (extended beyond the liquid) and the level
   * set psi whose negative part is the liquid, phi = H(-psi).
   * Components: u_0 .. u_{dim-1}, psi.
   */
  template <int dim>
  class TransportedFields
  {
  public:
    static constexpr unsigned int n_components        = dim + 1;
    static constexpr unsigned int level_set_component = dim;
    using VectorType = LinearAlgebra::distributed::Vector<double>;

    /** A locally owned mesh vertex that carries its own degrees of freedom. */
    struct Node
    {
      Point<dim>                                   point;
      std::array<types::global_dof_index, dim + 1> dofs;
    };

    explicit TransportedFields(
      const parallel::distributed::Triangulation<dim> &triangulation);

    /** Distribute degrees of freedom after a mesh change; fields are zero. */
    void
    setup_dofs();

    /** Set the fields to the given functions at every node. */
    void
    interpolate(const Function<dim> &level_set, const Function<dim> &velocity);

    /** Set the velocity to @p velocity (at its current time) at every node. */
    void
    set_velocity(const Function<dim> &velocity);

    /** Make hanging nodes and ghost entries consistent after a change. */
    void
    finalize();

    /** Vector with the layout of the fields, ghosted. */
    void
    initialize_vector(VectorType &vector) const;

    const std::vector<Node> &
    nodes() const
    {
      return owned_nodes;
    }

    /** The same mesh cell seen through this DoFHandler. */
    typename DoFHandler<dim>::active_cell_iterator
    cell_of(const typename Triangulation<dim>::active_cell_iterator &cell) const
    {
      return typename DoFHandler<dim>::active_cell_iterator(
        &dof_handler.get_triangulation(),
        cell->level(),
        cell->index(),
        &dof_handler);
    }

    const MappingQ1<dim>      mapping;
    const FESystem<dim>       fe;
    DoFHandler<dim>           dof_handler;
    AffineConstraints<double> constraints;
    IndexSet                  owned_dofs;
    IndexSet                  relevant_dofs;
    VectorType                fields;

  private:
    std::vector<Node> owned_nodes;
  };
} // namespace vefs

#endif
