#include <Epetra_Vector.h>
#include <vefs/component_wise_matrix.h>

#include <vector>

namespace vefs
{
  template <int dim>
  TrilinosWrappers::MPI::Vector
  velocity_components(const DoFHandler<dim> &dof_handler,
                      const unsigned int     liquid_index,
                      const IndexSet        &owned,
                      const IndexSet        &touched)
  {
    const MPI_Comm comm = dof_handler.get_triangulation().get_communicator();
    TrilinosWrappers::MPI::Vector        owned_components(owned, comm);
    std::vector<types::global_dof_index> dofs;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && cell->active_fe_index() == liquid_index)
        {
          const auto &fe = cell->get_fe();
          dofs.resize(fe.n_dofs_per_cell());
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            {
              const unsigned int c = fe.system_to_component_index(i).first;
              if (c < dim && owned.is_element(dofs[i]))
                owned_components(dofs[i]) = c;
            }
        }
    owned_components.compress(VectorOperation::insert);
    TrilinosWrappers::MPI::Vector components(owned, touched, comm);
    components = owned_components;
    return components;
  }

  std::unique_ptr<Epetra_CrsMatrix>
  component_wise_part(const TrilinosWrappers::SparseMatrix &matrix,
                      const TrilinosWrappers::MPI::Vector  &components)
  {
    const Epetra_CrsMatrix &whole = matrix.trilinos_matrix();
    // The component of each of the rank's columns, -1 if unknown; looked up
    // once, not once per entry.
    const Epetra_Vector   &known     = *components.trilinos_vector()(0);
    const Epetra_BlockMap &known_map = known.Map();
    std::vector<int>       column_component(whole.NumMyCols(), -1);
    for (int j = 0; j < whole.NumMyCols(); ++j)
      {
        const int lid = known_map.LID(whole.ColMap().GID(j));
        if (lid >= 0)
          column_component[j] = static_cast<int>(known[lid]);
      }
    std::vector<int> row_component(whole.NumMyRows(), -1);
    for (int i = 0; i < whole.NumMyRows(); ++i)
      row_component[i] =
        static_cast<int>(known[known_map.LID(whole.RowMap().GID(i))]);

    const auto kept = [&](const int row, const int column) {
      return column_component[column] < 0 ||
             column_component[column] == row_component[row];
    };
    std::vector<int> row_lengths(whole.NumMyRows(), 0);
    for (int i = 0; i < whole.NumMyRows(); ++i)
      {
        int     n;
        double *values;
        int    *columns;
        whole.ExtractMyRowView(i, n, values, columns);
        for (int k = 0; k < n; ++k)
          row_lengths[i] += kept(i, columns[k]);
      }
    auto                part = std::make_unique<Epetra_CrsMatrix>(Copy,
                                                   whole.RowMap(),
                                                   whole.ColMap(),
                                                   row_lengths.data(),
                                                   true);
    std::vector<int>    kept_columns;
    std::vector<double> kept_values;
    for (int i = 0; i < whole.NumMyRows(); ++i)
      {
        int     n;
        double *values;
        int    *columns;
        whole.ExtractMyRowView(i, n, values, columns);
        kept_columns.clear();
        kept_values.clear();
        for (int k = 0; k < n; ++k)
          if (kept(i, columns[k]))
            {
              kept_columns.push_back(columns[k]);
              kept_values.push_back(values[k]);
            }
        part->InsertMyValues(i,
                             kept_columns.size(),
                             kept_values.data(),
                             kept_columns.data());
      }
    part->FillComplete(whole.DomainMap(), whole.RangeMap());
    return part;
  }

  template TrilinosWrappers::MPI::Vector
  velocity_components<2>(const DoFHandler<2> &,
                         const unsigned int,
                         const IndexSet &,
                         const IndexSet &);
  template TrilinosWrappers::MPI::Vector
  velocity_components<3>(const DoFHandler<3> &,
                         const unsigned int,
                         const IndexSet &,
                         const IndexSet &);
} // namespace vefs
