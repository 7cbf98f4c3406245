#include <vefs/fields/vertex_field_transfer.h>

#include <algorithm>
#include <cstring>

namespace vefs
{
  template <int dim>
  VertexFieldTransfer<dim>::VertexFieldTransfer(
    parallel::distributed::Triangulation<dim> &mesh,
    const TransportedFields<dim>              &fields,
    const std::vector<Slot>                   &slots,
    LatticeSource                             *lattice_source)
    : mesh(mesh)
    , slots(slots)
    , child_weights(make_child_vertex_weights<dim>())
    , lattice_source(lattice_source)
  {
    for (const Slot &slot : slots)
      n_values += slot.components.size();
    // Every cell packs the same number of bytes: deal.II's fixed-size
    // transfer, cheaper than the variable one.
    handle = mesh.register_data_attach(
      [this, &fields](const typename Triangulation<dim>::cell_iterator &cell,
                      const typename Triangulation<dim>::CellStatus status) {
        return vertex_values(fields,
                             cell,
                             status == Triangulation<dim>::CELL_COARSEN);
      },
      false);
    if (!lattice_source)
      return;
    lattice_components = lattice_source->components();
    for (const auto &[slot, component] : lattice_components)
      AssertThrow(slot < slots.size(), ExcInternalError());
    lattice_handle = mesh.register_data_attach(
      [this](const typename Triangulation<dim>::cell_iterator &cell,
             const CellStatus                                  status) {
        const std::vector<double> lattice =
          this->lattice_source->pack(cell, status);
        AssertThrow(lattice.empty() ||
                      lattice.size() == FamilyLattice<dim>::n_points *
                                          lattice_components.size(),
                    ExcInternalError());
        std::vector<char> buffer(lattice.size() * sizeof(double));
        if (!lattice.empty())
          std::memcpy(buffer.data(), lattice.data(), buffer.size());
        return buffer;
      },
      /*returns_variable_size_data=*/true);
  }

  template <int dim>
  std::vector<char>
  VertexFieldTransfer<dim>::vertex_values(
    const TransportedFields<dim>                     &fields,
    const typename Triangulation<dim>::cell_iterator &cell,
    const bool                                        from_children) const
  {
    std::vector<char> buffer(GeometryInfo<dim>::vertices_per_cell * n_values *
                             sizeof(double));
    char             *next = buffer.data();
    for (const unsigned int v : GeometryInfo<dim>::vertex_indices())
      {
        // Vertex v of a parent is vertex v of its child v.
        const auto dof_cell =
          fields.cell_of(from_children ? cell->child(v) : cell);
        for (const Slot &slot : slots)
          for (const unsigned int c : slot.components)
            {
              const double value =
                (*slot.vector)(dof_cell->vertex_dof_index(v, c));
              std::memcpy(next, &value, sizeof(double));
              next += sizeof(double);
            }
      }
    return buffer;
  }

  template <int dim>
  void
  VertexFieldTransfer<dim>::write(
    const TransportedFields<dim>                            &fields,
    const typename Triangulation<dim>::active_cell_iterator &cell,
    const double                                            *values,
    const std::vector<VectorType *>                         &vectors) const
  {
    const auto dof_cell = fields.cell_of(cell);
    for (const unsigned int v : cell->vertex_indices())
      {
        unsigned int k = v * n_values;
        for (unsigned int s = 0; s < slots.size(); ++s)
          for (const unsigned int c : slots[s].components)
            {
              const types::global_dof_index dof =
                dof_cell->vertex_dof_index(v, c);
              if (vectors[s]->in_local_range(dof))
                (*vectors[s])(dof) = values[k];
              ++k;
            }
      }
  }

  template <int dim>
  void
  VertexFieldTransfer<dim>::write_lattice(
    const TransportedFields<dim>                     &fields,
    const typename Triangulation<dim>::cell_iterator &parent,
    const double                                     *lattice,
    const std::vector<VectorType *>                  &vectors) const
  {
    const unsigned int n_values = lattice_components.size();
    for (unsigned int child = 0; child < parent->n_children(); ++child)
      {
        const auto cell = fields.cell_of(parent->child(child));
        for (const unsigned int v : cell->vertex_indices())
          {
            const double *point =
              lattice + n_values * FamilyLattice<dim>::point(child, v);
            for (unsigned int k = 0; k < n_values; ++k)
              {
                const auto [slot, component] = lattice_components[k];
                const types::global_dof_index dof =
                  cell->vertex_dof_index(v, component);
                if (vectors[slot]->in_local_range(dof))
                  (*vectors[slot])(dof) = point[k];
              }
          }
      }
  }

  template <int dim>
  void
  VertexFieldTransfer<dim>::unpack(const TransportedFields<dim>    &fields,
                                   const std::vector<VectorType *> &vectors)
  {
    AssertThrow(vectors.size() == slots.size(), ExcInternalError());
    constexpr unsigned int n_vertices = GeometryInfo<dim>::vertices_per_cell;
    std::vector<double>    parent(n_vertices * n_values);
    std::vector<double>    child(n_vertices * n_values);
    mesh.notify_ready_to_unpack(
      handle,
      [&](
        const typename Triangulation<dim>::cell_iterator               &cell,
        const typename Triangulation<dim>::CellStatus                   status,
        const boost::iterator_range<std::vector<char>::const_iterator> &data) {
        AssertThrow(static_cast<std::size_t>(data.size()) ==
                      parent.size() * sizeof(double),
                    ExcInternalError());
        std::memcpy(parent.data(), &*data.begin(), data.size());
        if (status != Triangulation<dim>::CELL_REFINE)
          {
            write(fields, cell, parent.data(), vectors);
            return;
          }
        for (unsigned int c = 0; c < cell->n_children(); ++c)
          {
            std::fill(child.begin(), child.end(), 0.);
            for (unsigned int v = 0; v < n_vertices; ++v)
              for (const auto &[w, weight] : child_weights[c][v])
                for (unsigned int k = 0; k < n_values; ++k)
                  child[v * n_values + k] += weight * parent[w * n_values + k];
            write(fields, cell->child(c), child.data(), vectors);
          }
      });
    if (!lattice_source)
      return;

    lattice_source->start_keeping(mesh);
    std::vector<double> lattice;
    mesh.notify_ready_to_unpack(
      lattice_handle,
      [&](
        const typename Triangulation<dim>::cell_iterator               &cell,
        const CellStatus                                                status,
        const boost::iterator_range<std::vector<char>::const_iterator> &data) {
        if (data.empty())
          return;
        lattice.resize(data.size() / sizeof(double));
        std::memcpy(lattice.data(), &*data.begin(), data.size());
        if (status == Triangulation<dim>::CELL_REFINE)
          write_lattice(fields, cell, lattice.data(), vectors);
        else
          lattice_source->keep(
            typename Triangulation<dim>::active_cell_iterator(cell),
            lattice.data());
      });
  }

  template <int dim>
  std::vector<typename TransportedFields<dim>::VectorType>
  carry_through_mesh_change(
    parallel::distributed::Triangulation<dim>                  &mesh,
    TransportedFields<dim>                                     &fields,
    const std::vector<typename VertexFieldTransfer<dim>::Slot> &slots,
    const std::function<void()>                                &change,
    typename VertexFieldTransfer<dim>::LatticeSource           *lattice_source)
  {
    std::vector<typename TransportedFields<dim>::VectorType> carried(
      slots.size());
    VertexFieldTransfer<dim> transfer(mesh, fields, slots, lattice_source);
    change();
    fields.setup_dofs();
    std::vector<typename TransportedFields<dim>::VectorType *> targets;
    for (auto &vector : carried)
      {
        fields.initialize_vector(vector);
        targets.push_back(&vector);
      }
    transfer.unpack(fields, targets);
    return carried;
  }

  template class VertexFieldTransfer<2>;
  template class VertexFieldTransfer<3>;
  template std::vector<TransportedFields<2>::VectorType>
  carry_through_mesh_change(parallel::distributed::Triangulation<2> &,
                            TransportedFields<2> &,
                            const std::vector<VertexFieldTransfer<2>::Slot> &,
                            const std::function<void()> &,
                            VertexFieldTransfer<2>::LatticeSource *);
  template std::vector<TransportedFields<3>::VectorType>
  carry_through_mesh_change(parallel::distributed::Triangulation<3> &,
                            TransportedFields<3> &,
                            const std::vector<VertexFieldTransfer<3>::Slot> &,
                            const std::function<void()> &,
                            VertexFieldTransfer<3>::LatticeSource *);
} // namespace vefs
