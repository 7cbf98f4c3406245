#include <vefs/field_extension.h>

namespace vefs
{
  template <int dim>
  void
  extend_flow_fields(TransportedFields<dim>                      &fields,
                     typename TransportedFields<dim>::VectorType &known,
                     const unsigned int                           n_layers)
  {
    using VectorType = typename TransportedFields<dim>::VectorType;
    // Every component but the level set, which is transported on its own.
    std::vector<unsigned int> components;
    for (unsigned int c = 0; c < fields.n_components; ++c)
      if (c != TransportedFields<dim>::level_set_component)
        components.push_back(c);

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

  template void
  extend_flow_fields<2>(TransportedFields<2> &,
                        TransportedFields<2>::VectorType &,
                        const unsigned int);
  template void
  extend_flow_fields<3>(TransportedFields<3> &,
                        TransportedFields<3>::VectorType &,
                        const unsigned int);
} // namespace vefs
