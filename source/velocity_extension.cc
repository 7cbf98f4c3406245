#include <vefs/velocity_extension.h>

namespace vefs
{
  template <int dim>
  void
  extend_velocity(TransportedFields<dim>                      &fields,
                  typename TransportedFields<dim>::VectorType &known,
                  const unsigned int                           n_layers)
  {
    using VectorType = typename TransportedFields<dim>::VectorType;

    for (const auto &node : fields.nodes())
      if (known(node.dofs[0]) == 0)
        for (unsigned int d = 0; d < dim; ++d)
          fields.fields(node.dofs[d]) = 0;
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
              Tensor<1, dim> average;
              unsigned int   n_known = 0;
              for (const unsigned int v : cell->vertex_indices())
                if (known(cell->vertex_dof_index(v, 0)) != 0)
                  {
                    ++n_known;
                    for (unsigned int d = 0; d < dim; ++d)
                      average[d] += fields.fields(cell->vertex_dof_index(v, d));
                  }
              if (n_known == 0 || n_known == cell->n_vertices())
                continue;
              average /= n_known;
              for (const unsigned int v : cell->vertex_indices())
                if (known(cell->vertex_dof_index(v, 0)) == 0)
                  {
                    count(cell->vertex_dof_index(v, 0)) += 1;
                    for (unsigned int d = 0; d < dim; ++d)
                      sum(cell->vertex_dof_index(v, d)) += average[d];
                  }
            }
        sum.compress(VectorOperation::add);
        count.compress(VectorOperation::add);

        for (const auto &node : fields.nodes())
          if (known(node.dofs[0]) == 0 && count(node.dofs[0]) > 0)
            {
              for (unsigned int d = 0; d < dim; ++d)
                fields.fields(node.dofs[d]) =
                  sum(node.dofs[d]) / count(node.dofs[0]);
              known(node.dofs[0]) = 1;
            }
        fields.finalize();
        known.update_ghost_values();
      }
  }

  template void
  extend_velocity<2>(TransportedFields<2> &,
                     TransportedFields<2>::VectorType &,
                     const unsigned int);
  template void
  extend_velocity<3>(TransportedFields<3> &,
                     TransportedFields<3>::VectorType &,
                     const unsigned int);
} // namespace vefs
