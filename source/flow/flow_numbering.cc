#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_renumbering.h>
#include <deal.II/dofs/dof_tools.h>

#include <vefs/flow/flow_numbering.h>

namespace vefs
{
  std::vector<IndexSet>
  FlowNumbering::flow_blocks(const IndexSet &set) const
  {
    return {set.get_view(0, start(1)), set.get_view(start(1), start(2))};
  }

  std::vector<IndexSet>
  FlowNumbering::all_parts(const IndexSet &set) const
  {
    // deal.II 9.4's DataOut divides by the size of each block.
    const unsigned int n_parts =
      n_dofs_of_part[2] + n_dofs_of_part[3] > 0 ? 4 : 2;
    std::vector<IndexSet> parts;
    for (unsigned int part = 0; part < n_parts; ++part)
      parts.push_back(set.get_view(start(part), start(part + 1)));
    return parts;
  }

  template <int dim>
  FlowNumbering
  renumber_flow_dofs(DoFHandler<dim>         &dof_handler,
                     const FlowElements<dim> &elements,
                     const unsigned int       fe_index)
  {
    const IndexSet interpolated =
      elements.interpolated_dofs(dof_handler, fe_index);
    const MPI_Comm comm = dof_handler.get_communicator();
    if (Utilities::MPI::sum(interpolated.n_elements(), comm) == 0)
      {
        // deal.II's component-wise numbering is the whole answer.
        std::vector<unsigned int> block_component(dim + 1, 0);
        block_component[dim] = 1;
        DoFRenumbering::component_wise(dof_handler, block_component);
        const auto n_per_block =
          DoFTools::count_dofs_per_fe_block(dof_handler, block_component);
        FlowNumbering numbering;
        numbering.n_dofs_of_part = {{n_per_block[0], n_per_block[1], 0, 0}};
        return numbering;
      }

    // Each owned dof lies on an owned cell: its part from there. One
    // renumbering, not deal.II's component-wise one and a second (each
    // took 0.3 s a step on the 3D ball at 2.5 mm).
    const IndexSet           &owned   = dof_handler.locally_owned_dofs();
    constexpr unsigned int    no_part = 4;
    std::vector<unsigned int> part_of_owned(owned.n_elements(), no_part);
    std::vector<types::global_dof_index> dofs;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && cell->active_fe_index() == fe_index)
        {
          const auto &fe = cell->get_fe();
          dofs.resize(fe.n_dofs_per_cell());
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            if (owned.is_element(dofs[i]))
              part_of_owned[owned.index_within_set(dofs[i])] =
                (fe.system_to_component_index(i).first < dim ? 0 : 1) +
                (interpolated.is_element(dofs[i]) ? 2 : 0);
        }
    std::array<types::global_dof_index, 4> n_owned = {};
    for (const unsigned int part : part_of_owned)
      {
        AssertThrow(part != no_part,
                    ExcMessage("An owned flow dof on no owned flow cell."));
        ++n_owned[part];
      }

    // Part by part, the ranks' owned dofs in the order of the ranks.
    FlowNumbering                          numbering;
    std::array<types::global_dof_index, 4> first_of_rank = {};
    const int                              ierr =
      MPI_Exscan(n_owned.data(),
                 first_of_rank.data(),
                 4,
                 Utilities::MPI::mpi_type_id_for_type<types::global_dof_index>,
                 MPI_SUM,
                 comm);
    AssertThrowMPI(ierr);
    // MPI_Exscan leaves rank 0's undefined.
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      first_of_rank = {};
    for (unsigned int part = 0; part < 4; ++part)
      numbering.n_dofs_of_part[part] = Utilities::MPI::sum(n_owned[part], comm);
    std::array<types::global_dof_index, 4> next;
    for (unsigned int part = 0; part < 4; ++part)
      next[part] = numbering.start(part) + first_of_rank[part];
    std::vector<types::global_dof_index> new_numbers;
    new_numbers.reserve(owned.n_elements());
    for (const unsigned int part : part_of_owned)
      new_numbers.push_back(next[part]++);
    dof_handler.renumber_dofs(new_numbers);
    return numbering;
  }

  template FlowNumbering
  renumber_flow_dofs(DoFHandler<2> &, const FlowElements<2> &, unsigned int);
  template FlowNumbering
  renumber_flow_dofs(DoFHandler<3> &, const FlowElements<3> &, unsigned int);
} // namespace vefs
