#include <vefs/transport/field_extension.h>

namespace vefs
{
  namespace
  {
    /**
     * The owned cells and their vertices as local indices into the vectors
     * of the fields, and the cells around each vertex: the extension walks
     * outward from the known nodes and visits the cells at its front only,
     * not the whole mesh once per layer.
     */
    template <int dim>
    class CellVertexGraph
    {
    public:
      CellVertexGraph(const TransportedFields<dim> &fields,
                      const unsigned int            n_components)
        : n_components(n_components)
      {
        const auto        &partitioner = *fields.partitioner;
        const unsigned int n_local =
          partitioner.locally_owned_size() + partitioner.n_ghost_indices();
        std::vector<unsigned int> vertex_of_local(
          n_local,
          numbers::invalid_unsigned_int);
        for (const auto &cell : fields.dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
            for (const unsigned int v : cell->vertex_indices())
              {
                const unsigned int first = fields.local_entry(cell, v, 0);
                if (vertex_of_local[first] == numbers::invalid_unsigned_int)
                  {
                    vertex_of_local[first] = n_vertices();
                    for (unsigned int c = 0; c < n_components; ++c)
                      vertex_dofs.push_back(fields.local_entry(cell, v, c));
                  }
                cell_vertices.push_back(vertex_of_local[first]);
              }
        // The cells around each vertex, in cell order.
        cells_start.assign(n_vertices() + 1, 0);
        for (const unsigned int vertex : cell_vertices)
          ++cells_start[vertex + 1];
        for (unsigned int i = 0; i < n_vertices(); ++i)
          cells_start[i + 1] += cells_start[i];
        vertex_cells.resize(cell_vertices.size());
        std::vector<unsigned int> next(cells_start.begin(),
                                       cells_start.end() - 1);
        for (unsigned int k = 0; k < cell_vertices.size(); ++k)
          vertex_cells[next[cell_vertices[k]]++] = k / vertices_per_cell;
      }

      unsigned int
      n_cells() const
      {
        return cell_vertices.size() / vertices_per_cell;
      }

      unsigned int
      n_vertices() const
      {
        return vertex_dofs.size() / n_components;
      }

      /** Local index of component @p c at vertex @p vertex. */
      unsigned int
      dof(const unsigned int vertex, const unsigned int c) const
      {
        return vertex_dofs[vertex * n_components + c];
      }

      static constexpr unsigned int vertices_per_cell =
        GeometryInfo<dim>::vertices_per_cell;
      const unsigned int        n_components;
      std::vector<unsigned int> cell_vertices;
      std::vector<unsigned int> cells_start;
      std::vector<unsigned int> vertex_cells;

    private:
      std::vector<unsigned int> vertex_dofs;
    };
  } // namespace

  template <int dim>
  void
  extend_flow_fields(TransportedFields<dim>                      &fields,
                     typename TransportedFields<dim>::VectorType &known,
                     const unsigned int                           n_layers,
                     const std::vector<unsigned int>             &components)
  {
    using VectorType = typename TransportedFields<dim>::VectorType;

    for (const auto &node : fields.nodes())
      if (known(node.dofs[0]) == 0)
        for (const unsigned int c : components)
          fields.set_value(node, c, 0);
    fields.update_ghost_values();
    known.update_ghost_values();

    const CellVertexGraph<dim> graph(fields, fields.n_components);
    constexpr unsigned int     n_v = CellVertexGraph<dim>::vertices_per_cell;
    const auto                 is_known = [&](const unsigned int vertex) {
      return known.local_element(graph.dof(vertex, 0)) != 0;
    };
    // A cell adds to its unknown vertices only if it has known ones too.
    const auto is_front = [&](const unsigned int cell) {
      unsigned int n_known = 0;
      for (unsigned int v = 0; v < n_v; ++v)
        n_known += is_known(graph.cell_vertices[cell * n_v + v]);
      return n_known > 0 && n_known < n_v;
    };
    std::vector<bool> was_known(graph.n_vertices());
    for (unsigned int vertex = 0; vertex < graph.n_vertices(); ++vertex)
      was_known[vertex] = is_known(vertex);
    std::vector<unsigned int> front;
    for (unsigned int cell = 0; cell < graph.n_cells(); ++cell)
      if (is_front(cell))
        front.push_back(cell);

    VectorType sum, count;
    fields.initialize_vector(sum);
    fields.initialize_vector(count);
    std::vector<bool>   in_front(graph.n_cells(), false);
    std::vector<double> average(fields.n_components);
    for (unsigned int layer = 0; layer < n_layers; ++layer)
      {
        sum   = 0;
        count = 0;
        // In cell order, as the sums were always made.
        for (const unsigned int cell : front)
          {
            const unsigned int *vertices = &graph.cell_vertices[cell * n_v];
            for (const unsigned int c : components)
              average[c] = 0;
            unsigned int n_known = 0;
            for (unsigned int v = 0; v < n_v; ++v)
              if (is_known(vertices[v]))
                {
                  ++n_known;
                  for (const unsigned int c : components)
                    average[c] += fields.local_value(graph.dof(vertices[v], c));
                }
            for (const unsigned int c : components)
              average[c] /= n_known;
            for (unsigned int v = 0; v < n_v; ++v)
              if (!is_known(vertices[v]))
                {
                  count.local_element(graph.dof(vertices[v], 0)) += 1;
                  for (const unsigned int c : components)
                    sum.local_element(graph.dof(vertices[v], c)) += average[c];
                }
          }
        sum.compress(VectorOperation::add);
        count.compress(VectorOperation::add);

        for (const auto &node : fields.nodes())
          if (known(node.dofs[0]) == 0 && count(node.dofs[0]) > 0)
            {
              for (const unsigned int c : components)
                fields.set_value(node,
                                 c,
                                 sum(node.dofs[c]) / count(node.dofs[0]));
              known(node.dofs[0]) = 1;
            }
        fields.finalize();
        known.update_ghost_values();

        // The next front: the cells of this one and those around the
        // vertices known since, as far as they still have unknown vertices.
        for (const unsigned int cell : front)
          in_front[cell] = true;
        for (unsigned int vertex = 0; vertex < graph.n_vertices(); ++vertex)
          if (!was_known[vertex] && is_known(vertex))
            {
              was_known[vertex] = true;
              for (unsigned int k = graph.cells_start[vertex];
                   k < graph.cells_start[vertex + 1];
                   ++k)
                in_front[graph.vertex_cells[k]] = true;
            }
        front.clear();
        for (unsigned int cell = 0; cell < graph.n_cells(); ++cell)
          if (in_front[cell])
            {
              in_front[cell] = false;
              if (is_front(cell))
                front.push_back(cell);
            }
      }
  }

  template <int dim>
  std::vector<unsigned int>
  flow_components(const TransportedFields<dim> &fields)
  {
    // The level set is transported on its own.
    std::vector<unsigned int> components;
    for (unsigned int c = 0; c < fields.n_components; ++c)
      if (c != TransportedFields<dim>::level_set_component)
        components.push_back(c);
    return components;
  }

  template <int dim>
  std::vector<unsigned int>
  velocity_components()
  {
    std::vector<unsigned int> components;
    for (unsigned int d = 0; d < dim; ++d)
      components.push_back(d);
    return components;
  }

  template <int dim>
  std::vector<unsigned int>
  stress_components(const TransportedFields<dim> &fields)
  {
    std::vector<unsigned int> components;
    if (fields.has_stress())
      for (unsigned int i = 0; i < TransportedFields<dim>::n_stress_components;
           ++i)
        components.push_back(TransportedFields<dim>::first_stress_component +
                             i);
    // The dumbbells' fields are the stress's.
    for (unsigned int c = 0; c < dim * fields.n_dumbbell_fields; ++c)
      components.push_back(fields.first_dumbbell_component + c);
    return components;
  }

  template <int dim>
  std::vector<unsigned int>
  acceleration_components(const TransportedFields<dim> &fields)
  {
    std::vector<unsigned int> components;
    if (fields.has_acceleration())
      for (unsigned int d = 0; d < dim; ++d)
        components.push_back(fields.first_acceleration_component + d);
    return components;
  }

  template <int dim>
  std::vector<unsigned int>
  velocity_and_acceleration_components(const TransportedFields<dim> &fields)
  {
    std::vector<unsigned int> components = velocity_components<dim>();
    for (const unsigned int c : acceleration_components(fields))
      components.push_back(c);
    return components;
  }

  template <int dim>
  void
  unflag_nodes_outside_liquid(
    const TransportedFields<dim>                &fields,
    typename TransportedFields<dim>::VectorType &known)
  {
    unflag_nodes_outside_liquid<dim>(fields, known, [](const Point<dim> &) {
      return true;
    });
  }

  template <int dim>
  void
  unflag_nodes_outside_liquid(
    const TransportedFields<dim>                          &fields,
    typename TransportedFields<dim>::VectorType           &known,
    const std::function<bool(const dealii::Point<dim> &)> &selected)
  {
    for (const auto &node : fields.nodes())
      if (fields.level_set(node) > 0 && selected(node.point))
        known(node.dofs[0]) = 0;
    known.update_ghost_values();
  }

  template void
  extend_flow_fields<2>(TransportedFields<2> &,
                        TransportedFields<2>::VectorType &,
                        const unsigned int,
                        const std::vector<unsigned int> &);
  template void
  extend_flow_fields<3>(TransportedFields<3> &,
                        TransportedFields<3>::VectorType &,
                        const unsigned int,
                        const std::vector<unsigned int> &);
  template std::vector<unsigned int>
  flow_components<2>(const TransportedFields<2> &);
  template std::vector<unsigned int>
  flow_components<3>(const TransportedFields<3> &);
  template std::vector<unsigned int>
  velocity_components<2>();
  template std::vector<unsigned int>
  velocity_components<3>();
  template std::vector<unsigned int>
  stress_components<2>(const TransportedFields<2> &);
  template std::vector<unsigned int>
  stress_components<3>(const TransportedFields<3> &);
  template std::vector<unsigned int>
  acceleration_components<2>(const TransportedFields<2> &);
  template std::vector<unsigned int>
  acceleration_components<3>(const TransportedFields<3> &);
  template std::vector<unsigned int>
  velocity_and_acceleration_components<2>(const TransportedFields<2> &);
  template std::vector<unsigned int>
  velocity_and_acceleration_components<3>(const TransportedFields<3> &);
  template void
  unflag_nodes_outside_liquid<2>(const TransportedFields<2> &,
                                 TransportedFields<2>::VectorType &);
  template void
  unflag_nodes_outside_liquid<3>(const TransportedFields<3> &,
                                 TransportedFields<3>::VectorType &);
  template void
  unflag_nodes_outside_liquid<2>(
    const TransportedFields<2> &,
    TransportedFields<2>::VectorType &,
    const std::function<bool(const dealii::Point<2> &)> &);
  template void
  unflag_nodes_outside_liquid<3>(
    const TransportedFields<3> &,
    TransportedFields<3>::VectorType &,
    const std::function<bool(const dealii::Point<3> &)> &);
} // namespace vefs
