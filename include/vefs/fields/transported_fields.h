#ifndef vefs_transported_fields_h
#define vefs_transported_fields_h

#include <deal.II/base/function.h>
#include <deal.II/base/index_set.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/la_parallel_vector.h>

#include <vefs/fields/coarsened_detail.h>

#include <array>
#include <vector>

namespace vefs
{
  using namespace dealii;

  /**
   * The fields carried along the characteristics, as continuous Q1 fields on
   * the whole cavity: the velocity (extended beyond the liquid), the level
   * set psi whose negative part is the liquid, phi = H(-psi), and, in the
   * viscoelastic and elastic regimes only, the extra stress sigma (extended
   * beyond the liquid like the velocity).
   * Components: u_0 .. u_{dim-1}, psi, then the independent components of
   * sigma in the order of SymmetricTensor<2, dim>::unrolled_index().
   */
  template <int dim>
  class TransportedFields
  {
  public:
    static constexpr unsigned int level_set_component    = dim;
    static constexpr unsigned int first_stress_component = dim + 1;
    static constexpr unsigned int n_stress_components    = dim * (dim + 1) / 2;
    static constexpr unsigned int max_components =
      dim + 1 + n_stress_components;
    using VectorType = LinearAlgebra::distributed::Vector<double>;

    /** A locally owned mesh vertex that carries its own degrees of freedom. */
    struct Node
    {
      Point<dim>                                          point;
      std::array<types::global_dof_index, max_components> dofs;
    };

    /**
     * @p periodic_directions: the coordinate directions whose two walls
     * (boundary ids 2d and 2d+1) are periodic.
     */
    TransportedFields(
      const parallel::distributed::Triangulation<dim> &triangulation,
      const bool                                       with_stress,
      const std::vector<unsigned int>                 &periodic_directions);

    bool
    has_stress() const
    {
      return n_components > first_stress_component;
    }

    /** The velocity stored at @p node. */
    Tensor<1, dim>
    velocity(const Node &node) const
    {
      Tensor<1, dim> u;
      for (unsigned int d = 0; d < dim; ++d)
        u[d] = fields(node.dofs[d]);
      return u;
    }

    /** Distribute degrees of freedom after a mesh change; fields are zero. */
    void
    setup_dofs();

    /**
     * Set the fields to the given functions at every node; the stress (if
     * any) to @p stress, whose components are in unrolled order.
     */
    void
    interpolate(const Function<dim> &level_set,
                const Function<dim> &velocity,
                const Function<dim> *stress = nullptr);

    /** Set the velocity to @p velocity (at its current time) at every node. */
    void
    set_velocity(const Function<dim> &velocity);

    /**
     * Make hanging nodes and ghost entries consistent after a change (of
     * the fields and of the level set gradient).
     */
    void
    finalize();

    /**
     * Set the constrained entries (hanging nodes, periodic walls) of
     * @p vector, a vector with the layout of the fields whose ghost values
     * are up to date; its ghost values are stale afterwards. The same
     * values as AffineConstraints::distribute(), without its ghosted copy
     * of the whole vector (which costs a new MPI partitioner per call).
     */
    void
    distribute_constraints(VectorType &vector) const;

    /** Vector with the layout of the fields, ghosted; all such vectors
     * share one MPI partitioner, made once per mesh. */
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

    /** dim + 1, plus the stress components if there is a stress. */
    const unsigned int                                 n_components;
    const MappingQ1<dim>                               mapping;
    const FESystem<dim>                                fe;
    DoFHandler<dim>                                    dof_handler;
    AffineConstraints<double>                          constraints;
    IndexSet                                           owned_dofs;
    IndexSet                                           relevant_dofs;
    std::shared_ptr<const Utilities::MPI::Partitioner> partitioner;
    VectorType                                         fields;
    /**
     * The gradient of the level set, carried along the characteristics with
     * it by the gradient-augmented transport (FieldHermite): same layout
     * as @p fields, the derivative in direction d in the slot of velocity
     * component d (the other slots are unused).
     */
    VectorType level_set_gradient;
    /**
     * The fields of the cells the last mesh change coarsened, at their
     * former children's vertices, until the advection has read them ('Band
     * placement = predicted, one change'); empty otherwise.
     */
    CoarsenedDetail<dim> coarsened_detail;

  private:
    /** The owned lines of @p constraints in local vector indices. */
    void
    localize_constraints();

    const std::vector<unsigned int> periodic_directions;
    std::vector<Node>               owned_nodes;
    /**
     * Whether every source of an owned constrained entry is owned or a ghost
     * (then distribute_constraints() uses the local lines below).
     */
    bool                                         constraints_are_local = false;
    std::vector<unsigned int>                    constrained_entries;
    std::vector<double>                          inhomogeneities;
    std::vector<unsigned int>                    sources_start;
    std::vector<std::pair<unsigned int, double>> sources;
  };
} // namespace vefs

#endif
