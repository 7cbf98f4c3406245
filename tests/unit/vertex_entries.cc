// TransportedFields::vertex_entries() and the accessors that read through
// it (transported_fields.h; a table that setup_dofs() makes per active
// cell): the local index of each vertex's first component, component c at
// entry + c, in place of deal.II's DoFAccessor::vertex_dof_index(v, c) and
// the global access to the vector. On make_box_with_finer_patch() (hanging
// nodes, and on 2 ranks ghost cells across the partition), with the stress
// and the acceleration (the most components without dumbbells), each
// component set to a different smooth function: for every owned and ghost
// cell, vertex and component, the entry's value, value_at() and entry_at()
// of a copy (copy_to()) must equal the vector read at vertex_dof_index(v, c)
// (exactly: it is the same entry), and the entry's global index must be
// vertex_dof_index(v, c).
// Checked again after a mesh change (every cell with x < 0 refined, then
// setup_dofs()). 1 and 2 ranks print the same.

#include "unit_test.h"

#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>

#include <vefs/fields/transported_fields.h>

#include <iostream>

using namespace dealii;

namespace
{
  /** The fields set up on the present mesh, filled, and compared. */
  template <int dim>
  void
  compare(vefs::TransportedFields<dim> &fields,
          const std::string            &label,
          std::ostream                 &out)
  {
    const MPI_Comm comm = MPI_COMM_WORLD;
    fields.setup_dofs();
    const unit_test::Smooth<dim> field(fields.n_components, 0.3);
    for (const auto &node : fields.nodes())
      for (unsigned int c = 0; c < fields.n_components; ++c)
        fields.set_value(node, c, field.value(node.point, c));
    fields.finalize();
    typename vefs::TransportedFields<dim>::VectorType copy;
    fields.copy_to(copy);

    unsigned int wrong_values = 0, wrong_indices = 0, ghost_cells = 0,
                 owned_cells = 0;
    for (const auto &cell : fields.dof_handler.active_cell_iterators())
      if (!cell->is_artificial())
        {
          (cell->is_locally_owned() ? owned_cells : ghost_cells) += 1;
          const auto entries = fields.vertex_entries(cell);
          for (const unsigned int v : cell->vertex_indices())
            for (unsigned int c = 0; c < fields.n_components; ++c)
              {
                const double value =
                  fields.vector()(cell->vertex_dof_index(v, c));
                if (fields.local_value(entries[v] + c) != value ||
                    fields.value_at(cell, v, c) != value ||
                    fields.entry_at(copy, cell, v, c) != value)
                  ++wrong_values;
                if (fields.partitioner->local_to_global(entries[v] + c) !=
                    cell->vertex_dof_index(v, c))
                  ++wrong_indices;
              }
        }

    unit_test::check_zero(out,
                          label + "values that differ from vertex_dof_index's",
                          Utilities::MPI::sum(wrong_values, comm));
    unit_test::check_zero(out,
                          label +
                            "entries not at vertex_dof_index's global index",
                          Utilities::MPI::sum(wrong_indices, comm));
    // Every cell is owned on one rank; on 2 ranks each also sees ghosts.
    const auto &triangulation = fields.dof_handler.get_triangulation();
    out << label << "every cell checked: "
        << (Utilities::MPI::sum(owned_cells, comm) ==
                triangulation.n_global_active_cells()
              ? "yes"
              : "NO")
        << '\n';
    const bool ghosts_expected = Utilities::MPI::n_mpi_processes(comm) > 1;
    out << label << "ghost cells checked where there are ghosts: "
        << ((Utilities::MPI::min(ghost_cells, comm) > 0) == ghosts_expected
              ? "yes"
              : "NO")
        << '\n';
  }

  template <int dim>
  void
  check(std::ostream &out)
  {
    const MPI_Comm                            comm = MPI_COMM_WORLD;
    parallel::distributed::Triangulation<dim> triangulation(comm);
    unit_test::make_box_with_finer_patch(triangulation);

    vefs::TransportedFields<dim> fields(triangulation, true, true, {});
    const std::string            label = std::to_string(dim) + "D, ";
    out << label << "components per vertex: " << fields.n_components << '\n';
    compare(fields, label, out);

    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned() && cell->center()[0] < 0)
        cell->set_refine_flag();
    triangulation.execute_coarsening_and_refinement();
    compare(fields, label + "after a mesh change, ", out);
  }
} // namespace

int
main(int argc, char **argv)
{
  return unit_test::run(argc, argv, [](std::ostream &out) {
    check<2>(out);
    check<3>(out);
  });
}
