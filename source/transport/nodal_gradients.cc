#include <vefs/transport/nodal_gradients.h>

namespace vefs
{
  template <int dim>
  std::array<typename TransportedFields<dim>::VectorType, dim>
  recover_nodal_gradients(const TransportedFields<dim> &fields,
                          const unsigned int            n_components)
  {
    std::array<typename TransportedFields<dim>::VectorType, dim> gradients;
    typename TransportedFields<dim>::VectorType                  n_cells;
    fields.initialize_vector(n_cells);
    for (auto &gradient : gradients)
      fields.initialize_vector(gradient);

    for (const auto &cell : fields.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const auto entries = fields.vertex_entries(cell);
          for (unsigned int c = 0; c < n_components; ++c)
            for (const unsigned int v : cell->vertex_indices())
              {
                const unsigned int entry = entries[v] + c;
                n_cells.local_element(entry) += 1;
                for (unsigned int j = 0; j < dim; ++j)
                  {
                    // The Q1 derivative along the edge through v in
                    // direction j.
                    const unsigned int w = v ^ (1u << j);
                    const double       h =
                      cell->vertex(1u << j)[j] - cell->vertex(0)[j];
                    const unsigned int upper = (v >> j) & 1 ? v : w;
                    const unsigned int lower = (v >> j) & 1 ? w : v;
                    const double       difference =
                      fields.local_value(entries[upper] + c) -
                      fields.local_value(entries[lower] + c);
                    gradients[j].local_element(entry) += difference / h;
                  }
              }
        }

    n_cells.compress(VectorOperation::add);
    for (auto &gradient : gradients)
      {
        gradient.compress(VectorOperation::add);
        for (unsigned int i = 0; i < gradient.locally_owned_size(); ++i)
          if (n_cells.local_element(i) > 0)
            gradient.local_element(i) /= n_cells.local_element(i);
        gradient.update_ghost_values();
      }
    return gradients;
  }

  template std::array<TransportedFields<2>::VectorType, 2>
  recover_nodal_gradients<2>(const TransportedFields<2> &, const unsigned int);
  template std::array<TransportedFields<3>::VectorType, 3>
  recover_nodal_gradients<3>(const TransportedFields<3> &, const unsigned int);
} // namespace vefs
