#include <vefs/field_extension.h>

namespace vefs
{
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
          fields.fields(node.dofs[c]) = 0;
    fields.fields.update_ghost_values();
    known.update_ghost_values();

    VectorType sum, count;
    fields.initialize_vector(sum);
    fields.initialize_vector(count);
    for (unsigned int layer = 0; layer < n_layers; ++layer)
      {
        sum   = 0;
        count = 0;
        for (const auto &cell : fields.dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              Tensor<1, TransportedFields<dim>::max_components> average;
              unsigned int                                      n_known = 0;
              for (const unsigned int v : cell->vertex_indices())
                if (known(cell->vertex_dof_index(v, 0)) != 0)
                  {
                    ++n_known;
                    for (const unsigned int c : components)
                      average[c] += fields.fields(cell->vertex_dof_index(v, c));
                  }
              if (n_known == 0 || n_known == cell->n_vertices())
                continue;
              average /= n_known;
              for (const unsigned int v : cell->vertex_indices())
                if (known(cell->vertex_dof_index(v, 0)) == 0)
                  {
                    count(cell->vertex_dof_index(v, 0)) += 1;
                    for (const unsigned int c : components)
                      sum(cell->vertex_dof_index(v, c)) += average[c];
                  }
            }
        sum.compress(VectorOperation::add);
        count.compress(VectorOperation::add);

        for (const auto &node : fields.nodes())
          if (known(node.dofs[0]) == 0 && count(node.dofs[0]) > 0)
            {
              for (const unsigned int c : components)
                fields.fields(node.dofs[c]) =
                  sum(node.dofs[c]) / count(node.dofs[0]);
              known(node.dofs[0]) = 1;
            }
        fields.finalize();
        known.update_ghost_values();
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
    for (unsigned int c = TransportedFields<dim>::first_stress_component;
         c < fields.n_components;
         ++c)
      components.push_back(c);
    return components;
  }

  template <int dim>
  void
  unflag_nodes_outside_liquid(
    const TransportedFields<dim>                &fields,
    typename TransportedFields<dim>::VectorType &known)
  {
    for (const auto &node : fields.nodes())
      if (fields.fields(
            node.dofs[TransportedFields<dim>::level_set_component]) > 0)
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
  template void
  unflag_nodes_outside_liquid<2>(const TransportedFields<2> &,
                                 TransportedFields<2>::VectorType &);
  template void
  unflag_nodes_outside_liquid<3>(const TransportedFields<3> &,
                                 TransportedFields<3>::VectorType &);
} // namespace vefs
