#ifndef vefs_transported_fields_h
#define vefs_transported_fields_h

#include <deal.II/base/function.h>
#include <deal.II/base/geometry_info.h>
#include <deal.II/base/index_set.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/la_parallel_vector.h>

#include <vefs/compat/local_constraint_lines.h>

#include <array>
#include <type_traits>
#include <vector>

namespace vefs
{
  using namespace dealii;

  /**
   * The fields carried along the characteristics, as continuous Q1 fields on
   * the whole cavity: the velocity (extended beyond the liquid), the level
   * set psi whose negative part is the liquid, phi = H(-psi), and, in the
   * viscoelastic and elastic regimes only, the extra stress sigma (extended
   * beyond the liquid like the velocity), and with the second-order time
   * scheme only, the acceleration a of the last flow step (extended like
   * the velocity; doc/time_step_flow.md, "The second-order scheme").
   * With 'Material/Stress model = dumbbells', the N_f configuration fields
   * q_1 .. q_N_f follow (doc/dumbbells.md), and sigma holds their ensemble
   * stress. Components: u_0 .. u_{dim-1}, psi, then the independent
   * components of sigma in the order of
   * SymmetricTensor<2, dim>::unrolled_index(), then a_0 .. a_{dim-1}, then
   * the dim components of each q_i.
   */
  template <int dim>
  class TransportedFields
  {
  public:
    static constexpr unsigned int level_set_component    = dim;
    static constexpr unsigned int first_stress_component = dim + 1;
    static constexpr unsigned int n_stress_components    = dim * (dim + 1) / 2;
    static constexpr unsigned int max_components =
      dim + 1 + n_stress_components + dim;
    using VectorType = LinearAlgebra::distributed::Vector<double>;

    /**
     * The degrees of freedom of one vertex: FE_Q(1)^n_components numbers
     * the components of a vertex consecutively (setup_dofs() checks it), so
     * the first index names them all, however many components there are.
     */
    struct VertexDofs
    {
      types::global_dof_index first = numbers::invalid_dof_index;

      types::global_dof_index
      operator[](const unsigned int component) const
      {
        return first + component;
      }
    };

    /** A locally owned mesh vertex that carries its own degrees of freedom. */
    struct Node
    {
      Point<dim> point;
      VertexDofs dofs;
    };

    /**
     * @p periodic_directions: the coordinate directions whose two walls
     * (boundary ids 2d and 2d+1) are periodic; @p n_dumbbell_fields: N_f,
     * zero without dumbbells (they need @p with_stress).
     */
    TransportedFields(
      const parallel::distributed::Triangulation<dim> &triangulation,
      const bool                                       with_stress,
      const bool                                       with_acceleration,
      const std::vector<unsigned int>                 &periodic_directions,
      const unsigned int                               n_dumbbell_fields = 0);

    bool
    has_stress() const
    {
      return with_stress;
    }

    bool
    has_acceleration() const
    {
      return with_acceleration;
    }

    /**
     * @name Values at an owned node (nodes()). The setters write the owned
     * entry only: call finalize() after the last one.
     */
    /** @{ */
    Tensor<1, dim>
    velocity(const Node &node) const
    {
      return velocity_slots(fields, node);
    }

    void
    set_velocity(const Node &node, const Tensor<1, dim> &u)
    {
      set_velocity_slots(fields, node, u);
    }

    /**
     * The velocity slots of @p vector, a vector of this layout, at
     * @p node: for the vectors that keep a vector field in them (the
     * level set gradient).
     */
    static Tensor<1, dim>
    velocity_slots(const VectorType &vector, const Node &node)
    {
      Tensor<1, dim> u;
      for (unsigned int d = 0; d < dim; ++d)
        u[d] = vector(node.dofs[d]);
      return u;
    }

    static void
    set_velocity_slots(VectorType           &vector,
                       const Node           &node,
                       const Tensor<1, dim> &u)
    {
      for (unsigned int d = 0; d < dim; ++d)
        vector(node.dofs[d]) = u[d];
    }

    double
    level_set(const Node &node) const
    {
      return fields(node.dofs[level_set_component]);
    }

    void
    set_level_set(const Node &node, const double psi)
    {
      fields(node.dofs[level_set_component]) = psi;
    }

    /** Only if has_stress(). */
    SymmetricTensor<2, dim>
    stress(const Node &node) const
    {
      SymmetricTensor<2, dim> sigma;
      for (unsigned int i = 0; i < n_stress_components; ++i)
        sigma.access_raw_entry(i) =
          fields(node.dofs[first_stress_component + i]);
      return sigma;
    }

    void
    set_stress(const Node &node, const SymmetricTensor<2, dim> &sigma)
    {
      for (unsigned int i = 0; i < n_stress_components; ++i)
        fields(node.dofs[first_stress_component + i]) =
          sigma.access_raw_entry(i);
    }

    /** Only if has_acceleration(). */
    Tensor<1, dim>
    acceleration(const Node &node) const
    {
      return acceleration_slots(fields, node);
    }

    /**
     * The acceleration slots of @p vector, a vector of this layout (a copy
     * of the fields from before the flow step), at @p node.
     */
    Tensor<1, dim>
    acceleration_slots(const VectorType &vector, const Node &node) const
    {
      Tensor<1, dim> a;
      for (unsigned int d = 0; d < dim; ++d)
        a[d] = vector(node.dofs[first_acceleration_component + d]);
      return a;
    }

    void
    set_acceleration(const Node &node, const Tensor<1, dim> &a)
    {
      for (unsigned int d = 0; d < dim; ++d)
        fields(node.dofs[first_acceleration_component + d]) = a[d];
    }

    /** Configuration field @p i at @p node; only with dumbbells. */
    Tensor<1, dim>
    dumbbell(const Node &node, const unsigned int i) const
    {
      Tensor<1, dim> q;
      for (unsigned int d = 0; d < dim; ++d)
        q[d] = fields(node.dofs[first_dumbbell_component + dim * i + d]);
      return q;
    }

    void
    set_dumbbell(const Node           &node,
                 const unsigned int    i,
                 const Tensor<1, dim> &q)
    {
      for (unsigned int d = 0; d < dim; ++d)
        fields(node.dofs[first_dumbbell_component + dim * i + d]) = q[d];
    }

    /** Component @p c of the layout above, for loops over all fields. */
    double
    value(const Node &node, const unsigned int c) const
    {
      return fields(node.dofs[c]);
    }

    void
    set_value(const Node &node, const unsigned int c, const double value)
    {
      fields(node.dofs[c]) = value;
    }

    /** @} */

    /**
     * @name Values at vertex @p v of a cell (or a line) of dof_handler
     * (cell_of()), owned or ghost: the gathers of cell loops.
     */
    /** @{ */
    template <typename CellIterator>
    Tensor<1, dim>
    velocity_at(const CellIterator &cell, const unsigned int v) const
    {
      Tensor<1, dim> u;
      for (unsigned int d = 0; d < dim; ++d)
        u[d] = entry_at(fields, cell, v, d);
      return u;
    }

    template <typename CellIterator>
    double
    level_set_at(const CellIterator &cell, const unsigned int v) const
    {
      return entry_at(fields, cell, v, level_set_component);
    }

    /** Only if has_stress(). */
    template <typename CellIterator>
    SymmetricTensor<2, dim>
    stress_at(const CellIterator &cell, const unsigned int v) const
    {
      SymmetricTensor<2, dim> sigma;
      for (unsigned int i = 0; i < n_stress_components; ++i)
        sigma.access_raw_entry(i) =
          entry_at(fields, cell, v, first_stress_component + i);
      return sigma;
    }

    /** Only with dumbbells: configuration field @p i at a cell's vertex. */
    template <typename CellIterator>
    Tensor<1, dim>
    dumbbell_at(const CellIterator &cell,
                const unsigned int  v,
                const unsigned int  i) const
    {
      Tensor<1, dim> q;
      for (unsigned int d = 0; d < dim; ++d)
        q[d] =
          entry_at(fields, cell, v, first_dumbbell_component + dim * i + d);
      return q;
    }

    /** Only if has_acceleration(). */
    template <typename CellIterator>
    Tensor<1, dim>
    acceleration_at(const CellIterator &cell, const unsigned int v) const
    {
      Tensor<1, dim> a;
      for (unsigned int d = 0; d < dim; ++d)
        a[d] = entry_at(fields, cell, v, first_acceleration_component + d);
      return a;
    }

    template <typename CellIterator>
    double
    value_at(const CellIterator &cell,
             const unsigned int  v,
             const unsigned int  c) const
    {
      return entry_at(fields, cell, v, c);
    }

    /**
     * Component @p c at vertex @p v of an owned or ghost @p cell in
     * @p vector, which initialize_vector() or copy_to() made: the entry
     * local_entry() names (for active cells read from the table, not found
     * through deal.II's accessors).
     */
    template <typename Vector, typename CellIterator>
    decltype(auto)
    entry_at(Vector             &vector,
             const CellIterator &cell,
             const unsigned int  v,
             const unsigned int  c) const
    {
      // A reference to the entry of a mutable vector, its value otherwise.
      static_assert(std::is_same_v<std::remove_const_t<Vector>, VectorType>,
                    "A vector of the fields' type.");
      Assert(vector.get_partitioner() == partitioner,
             ExcMessage("A vector of another layout."));
      return vector.local_element(local_entry(cell, v, c));
    }

    /**
     * Whether the surface crosses an owned or ghost @p cell in the level set
     * slot of @p vector (the fields' layout): psi < 0 at one vertex and
     * psi > 0 at another.
     */
    template <typename CellIterator>
    bool
    surface_crosses(const VectorType &vector, const CellIterator &cell) const
    {
      bool inside = false, outside = false;
      for (const unsigned int v : cell->vertex_indices())
        {
          const double psi = entry_at(vector, cell, v, level_set_component);
          inside |= psi < 0;
          outside |= psi > 0;
        }
      return inside && outside;
    }

    /**
     * Local indices (owned or ghost, in the numbering of partitioner) of the
     * first component at each vertex of a cell: component c of vertex v is
     * entry first[v] + c, the components of a vertex being numbered in a row.
     * For an active cell a row of the table setup_dofs() makes; for walks
     * that read many components at points (the feet of the characteristics).
     */
    using VertexEntries =
      std::array<unsigned int, GeometryInfo<dim>::vertices_per_cell>;
    using DoFCellIterator = typename DoFHandler<dim>::active_cell_iterator;

    /** For an owned or ghost @p cell. */
    template <typename CellIterator>
    VertexEntries
    vertex_entries(const CellIterator &cell) const
    {
      if constexpr (std::is_same_v<CellIterator, DoFCellIterator>)
        return table_row(cell);
      else
        return look_up_vertex_entries(cell);
    }

    /**
     * Local index (owned or ghost) of component @p c at vertex @p v of an
     * owned or ghost @p cell (or line): for active cells from the table
     * setup_dofs() makes (in 3D deal.II finds a vertex of a cell through its
     * faces and lines).
     */
    template <typename CellIterator>
    unsigned int
    local_entry(const CellIterator &cell,
                const unsigned int  v,
                const unsigned int  c) const
    {
      if constexpr (std::is_same_v<CellIterator, DoFCellIterator>)
        return table_row(cell)[v] + c;
      else
        return partitioner->global_to_local(cell->vertex_dof_index(v, c));
    }

    /** For a vertex whose degrees of freedom this rank owns. */
    template <typename CellIterator>
    void
    set_velocity_at(const CellIterator   &cell,
                    const unsigned int    v,
                    const Tensor<1, dim> &u)
    {
      for (unsigned int d = 0; d < dim; ++d)
        entry_at(fields, cell, v, d) = u[d];
    }
    /** @} */

    /**
     * The entry of local index @p i (owned or ghost, in the numbering of
     * partitioner), for walks over local index tables.
     */
    double
    local_value(const unsigned int i) const
    {
      return fields.local_element(i);
    }

    /** Whether every owned entry of the fields is finite (this rank's). */
    bool
    owned_values_finite() const;

    /**
     * @p copy: the fields on the layout of the current mesh, ghosts up to
     * date (a velocity kept past the step that replaces it).
     */
    void
    copy_to(VectorType &copy) const;

    /**
     * The velocity the stress law of a step sees with 'Stress theta'
     * @p theta: theta u + (1 - theta) u*, u the fields' velocity and u* in
     * @p earlier (a copy_to() from before the flow step), into @p earlier,
     * ghosts up to date; with theta = 1 a copy of the fields. Only the
     * velocity slots of the result are meant.
     */
    void
    blend_velocity_into(VectorType &earlier, const double theta) const
    {
      if (theta == 1)
        {
          copy_to(earlier);
          return;
        }
      earlier.sadd(1 - theta, theta, fields);
      earlier.update_ghost_values();
    }

    /**
     * Exchange the fields' vector with @p other, a vector of the same
     * layout: the level set history lends its kept vectors to the fields'
     * own interpolation and takes them back.
     */
    void
    swap(VectorType &other)
    {
      fields.swap(other);
    }

    /**
     * @name The whole vectors, for the modules that hand them to deal.II
     * (FEValues, DataOut, SolutionTransfer) or carry them through a mesh
     * change (doc/code.md, 'The fields'); everything else goes through the
     * accessors above.
     */
    /** @{ */
    const VectorType &
    vector() const
    {
      return fields;
    }

    /** For the mesh transfer and the loading of a checkpoint only. */
    VectorType &
    mutable_vector()
    {
      return fields;
    }
    /** @} */

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

    /** Make hanging nodes and ghost entries consistent after a change. */
    void
    finalize();

    /** Update the ghost entries of the fields (no constraint changed). */
    void
    update_ghost_values() const
    {
      fields.update_ghost_values();
    }

    /**
     * Set the constrained entries (hanging nodes, periodic walls) of
     * @p vector, a vector with the layout of the fields whose ghost values
     * are up to date; its ghost values are stale afterwards. The same
     * values as AffineConstraints::distribute(), without its ghosted copy
     * of the whole vector (which costs a new MPI partitioner per call).
     */
    void
    distribute_constraints(VectorType &vector) const;

    /**
     * Make the hanging nodes and ghost entries of @p vector, a vector with
     * the layout of the fields whose owned entries are set, consistent:
     * what finalize() does to the fields.
     */
    void
    make_consistent(VectorType &vector) const;

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

    const bool with_stress;
    const bool with_acceleration;
    /** N_f; zero without dumbbells. */
    const unsigned int n_dumbbell_fields;
    /**
     * With dumbbells and 'Material/Dumbbell variance reduction': the
     * equilibrium fields p_1 .. p_N_f, one vector each for the whole domain
     * and the same on every rank (doc/dumbbells.md, "Variance
     * reduction"); empty otherwise.
     */
    std::vector<Tensor<1, dim>> dumbbell_controls;
    /**
     * dim + 1, plus the stress components if there is a stress, plus dim
     * if there is an acceleration, plus dim N_f.
     */
    const unsigned int n_components;
    /** After the stress, if any; meaningful only if has_acceleration(). */
    const unsigned int first_acceleration_component;
    /** After the acceleration, if any; meaningful only with dumbbells. */
    const unsigned int                                 first_dumbbell_component;
    const MappingQ1<dim>                               mapping;
    const FESystem<dim>                                fe;
    DoFHandler<dim>                                    dof_handler;
    AffineConstraints<double>                          constraints;
    IndexSet                                           owned_dofs;
    IndexSet                                           relevant_dofs;
    std::shared_ptr<const Utilities::MPI::Partitioner> partitioner;

  private:
    /** The owned lines of @p constraints in local vector indices. */
    void
    localize_constraints();

    /** The row of the vertex table for an owned or ghost active @p cell. */
    const VertexEntries &
    table_row(const DoFCellIterator &cell) const
    {
      AssertIndexRange(cell->active_cell_index(), entries_of_cells.size());
      return entries_of_cells[cell->active_cell_index()];
    }

    /** vertex_entries() from deal.II's numbering (what the table holds). */
    template <typename CellIterator>
    VertexEntries
    look_up_vertex_entries(const CellIterator &cell) const
    {
      VertexEntries first;
      for (const unsigned int v : cell->vertex_indices())
        first[v] = partitioner->global_to_local(cell->vertex_dof_index(v, 0));
      return first;
    }

    const std::vector<unsigned int> periodic_directions;
    std::vector<Node>               owned_nodes;
    /** vertex_entries() of each owned or ghost active cell, by its active
     * cell index; made by setup_dofs(). */
    std::vector<VertexEntries> entries_of_cells;
    VectorType                 fields;
    /**
     * Whether every source of an owned constrained entry is owned or a ghost
     * (then distribute_constraints() uses the local lines below).
     */
    bool constraints_are_local = false;
    /** The owned lines of @p constraints, by local vector indices. */
    LocalConstraintLines<unsigned int> local_constraints;
  };
} // namespace vefs

#endif
