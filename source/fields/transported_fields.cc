#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>

#include <vefs/compat/componentwise_constraints.h>
#include <vefs/fields/transported_fields.h>

#include <cmath>

namespace vefs
{
  template <int dim>
  TransportedFields<dim>::TransportedFields(
    const parallel::distributed::Triangulation<dim> &triangulation,
    const bool                                       with_stress,
    const bool                                       with_acceleration,
    const std::vector<unsigned int>                 &periodic_directions,
    const unsigned int                               n_dumbbell_fields)
    : with_stress(with_stress)
    , with_acceleration(with_acceleration)
    , n_dumbbell_fields(n_dumbbell_fields)
    , n_components(dim + 1 + (with_stress ? n_stress_components : 0) +
                   (with_acceleration ? dim : 0) + dim * n_dumbbell_fields)
    , first_acceleration_component(dim + 1 +
                                   (with_stress ? n_stress_components : 0))
    , first_dumbbell_component(first_acceleration_component +
                               (with_acceleration ? dim : 0))
    , fe(FE_Q<dim>(1), n_components)
    , dof_handler(triangulation)
    , periodic_directions(periodic_directions)
  {
  }

  template <int dim>
  void
  TransportedFields<dim>::setup_dofs()
  {
    dof_handler.distribute_dofs(fe);
    owned_dofs = dof_handler.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dof_handler, relevant_dofs);
    // Building a partitioner finds the owners of the ghosts by messages:
    // once per mesh, not per vector.
    partitioner = std::make_shared<Utilities::MPI::Partitioner>(
      owned_dofs,
      relevant_dofs,
      dof_handler.get_triangulation().get_communicator());

    make_componentwise_constraints(dof_handler,
                                   periodic_directions,
                                   relevant_dofs,
                                   constraints);

    initialize_vector(fields);
    localize_constraints();

    entries_of_cells.assign(dof_handler.get_triangulation().n_active_cells(),
                            VertexEntries());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (!cell->is_artificial())
        entries_of_cells[cell->active_cell_index()] =
          look_up_vertex_entries(cell);

    // FE_Q(1)^n_components: the i-th degree of freedom of a vertex belongs to
    // component i, so one vertex carries all fields of one node; deal.II
    // numbers them in a row.
    owned_nodes.clear();
    std::vector<bool> seen(owned_dofs.n_elements(), false);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          {
            const auto first = cell->vertex_dof_index(v, 0);
            if (!owned_dofs.is_element(first) ||
                constraints.is_constrained(first))
              continue;
            const auto local = owned_dofs.index_within_set(first);
            if (seen[local])
              continue;
            seen[local] = true;
            Node node;
            node.point      = cell->vertex(v);
            node.dofs.first = first;
            for (unsigned int c = 0; c < n_components; ++c)
              AssertThrow(cell->vertex_dof_index(v, c) == first + c,
                          ExcMessage("The components of a vertex are not "
                                     "numbered consecutively."));
            owned_nodes.push_back(node);
          }
  }

  template <int dim>
  void
  TransportedFields<dim>::initialize_vector(VectorType &vector) const
  {
    vector.reinit(partitioner);
  }

  template <int dim>
  void
  TransportedFields<dim>::interpolate(const Function<dim> &level_set,
                                      const Function<dim> &velocity,
                                      const Function<dim> *stress)
  {
    for (const auto &node : owned_nodes)
      {
        for (unsigned int d = 0; d < dim; ++d)
          fields(node.dofs[d]) = velocity.value(node.point, d);
        fields(node.dofs[level_set_component]) = level_set.value(node.point);
        if (has_stress())
          for (unsigned int i = 0; i < n_stress_components; ++i)
            fields(node.dofs[first_stress_component + i]) =
              stress ? stress->value(node.point, i) : 0.;
        // The acceleration of a new run comes from its first flow solve.
        if (has_acceleration())
          set_acceleration(node, Tensor<1, dim>());
      }
    finalize();
  }

  template <int dim>
  void
  TransportedFields<dim>::set_velocity(const Function<dim> &velocity)
  {
    for (const auto &node : owned_nodes)
      for (unsigned int d = 0; d < dim; ++d)
        fields(node.dofs[d]) = velocity.value(node.point, d);
    finalize();
  }

  template <int dim>
  void
  TransportedFields<dim>::finalize()
  {
    make_consistent(fields);
  }

  template <int dim>
  void
  TransportedFields<dim>::make_consistent(VectorType &vector) const
  {
    vector.update_ghost_values();
    distribute_constraints(vector);
    vector.update_ghost_values();
  }

  template <int dim>
  bool
  TransportedFields<dim>::owned_values_finite() const
  {
    bool finite = true;
    for (unsigned int i = 0; i < fields.locally_owned_size(); ++i)
      finite = finite && std::isfinite(fields.local_element(i));
    return finite;
  }

  template <int dim>
  void
  TransportedFields<dim>::copy_to(VectorType &copy) const
  {
    // On the current layout: an assignment would keep an older one of the
    // same local range.
    copy.reinit(partitioner);
    copy.copy_locally_owned_data_from(fields);
    copy.update_ghost_values();
  }

  template <int dim>
  void
  TransportedFields<dim>::localize_constraints()
  {
    const auto &partitioner = *this->partitioner;
    const bool  local       = local_constraints.reinit(
      constraints,
      [&](const types::global_dof_index index, unsigned int &place) {
        if (!owned_dofs.is_element(index))
          return false;
        place = partitioner.global_to_local(index);
        return true;
      },
      [&](const types::global_dof_index index, unsigned int &place) {
        if (!partitioner.in_local_range(index) &&
            !partitioner.is_ghost_entry(index))
          return false;
        place = partitioner.global_to_local(index);
        return true;
      });
    constraints_are_local = !Utilities::MPI::logical_or(
      !local,
      dof_handler.get_triangulation().get_communicator());
  }

  template <int dim>
  void
  TransportedFields<dim>::distribute_constraints(VectorType &vector) const
  {
    if (!constraints_are_local)
      {
        constraints.distribute(vector);
        return;
      }
    Assert(vector.get_partitioner()->locally_owned_size() ==
               fields.get_partitioner()->locally_owned_size() &&
             vector.get_partitioner()->n_ghost_indices() ==
               fields.get_partitioner()->n_ghost_indices(),
           ExcMessage("A vector with the layout of the fields."));
    // Constraints are closed: no source is itself constrained, so the
    // entries can be written in place.
    local_constraints.distribute(
      [&](const unsigned int i) { return vector.local_element(i); },
      [&](const unsigned int i, const double value) {
        vector.local_element(i) = value;
      });
  }

  template class TransportedFields<2>;
  template class TransportedFields<3>;
} // namespace vefs
