#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>

#include <vefs/compat/componentwise_constraints.h>

#include <unordered_map>

namespace vefs
{
  template <int dim>
  void
  make_componentwise_constraints(
    const DoFHandler<dim>           &dof_handler,
    const std::vector<unsigned int> &periodic_directions,
    const IndexSet                  &relevant_dofs,
    AffineConstraints<double>       &constraints)
  {
    const unsigned int n_components = dof_handler.get_fe().n_components();
    DoFHandler<dim>    scalar(dof_handler.get_triangulation());
    const FE_Q<dim>    q1(1);
    scalar.distribute_dofs(q1);
    IndexSet scalar_relevant;
    DoFTools::extract_locally_relevant_dofs(scalar, scalar_relevant);
    AffineConstraints<double> scalar_constraints(scalar_relevant);
    DoFTools::make_hanging_node_constraints(scalar, scalar_constraints);
    for (const unsigned int d : periodic_directions)
      DoFTools::make_periodicity_constraints(scalar,
                                             2 * d,
                                             2 * d + 1,
                                             d,
                                             scalar_constraints);
    scalar_constraints.close();

    // A scalar degree of freedom names a vertex; the system's first
    // component there.
    std::unordered_map<types::global_dof_index, types::global_dof_index>
      first_of;
    for (const auto &cell : scalar.active_cell_iterators())
      if (!cell->is_artificial())
        {
          const typename DoFHandler<dim>::active_cell_iterator system_cell(
            &dof_handler.get_triangulation(),
            cell->level(),
            cell->index(),
            &dof_handler);
          for (const unsigned int v : cell->vertex_indices())
            first_of.emplace(cell->vertex_dof_index(v, 0),
                             system_cell->vertex_dof_index(v, 0));
        }

    constraints.clear();
    constraints.reinit(relevant_dofs);
    for (const auto &line : scalar_constraints.get_lines())
      {
        const auto row = first_of.find(line.index);
        AssertThrow(row != first_of.end(), ExcInternalError());
        for (unsigned int c = 0; c < n_components; ++c)
          {
            constraints.add_line(row->second + c);
            for (const auto &[column, weight] : line.entries)
              constraints.add_entry(row->second + c,
                                    first_of.at(column) + c,
                                    weight);
            constraints.set_inhomogeneity(row->second + c, line.inhomogeneity);
          }
      }
    constraints.close();
  }

  template void
  make_componentwise_constraints<2>(const DoFHandler<2> &,
                                    const std::vector<unsigned int> &,
                                    const IndexSet &,
                                    AffineConstraints<double> &);
  template void
  make_componentwise_constraints<3>(const DoFHandler<3> &,
                                    const std::vector<unsigned int> &,
                                    const IndexSet &,
                                    AffineConstraints<double> &);
} // namespace vefs
