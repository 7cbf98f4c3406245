// The two hand-written distributions of hanging-node and periodic
// constraints against AffineConstraints::distribute(), bit for bit, on a
// mesh with hanging nodes and one periodic direction, 1 and 2 ranks:
// - TransportedFields::distribute_constraints() on the fields' vectors
//   (LinearAlgebra::distributed::Vector);
// - ConstraintDistribution::distribute() on Trilinos block vectors laid out
//   as the flow's (velocity block, pressure block).
// Each also prints whether all the sources of the owned constrained entries
// are on the rank (owned or ghost): only then does it use its own loop
// instead of falling back to deal.II's, and only then does the comparison
// test anything.

#include "unit_test.h"

#include <deal.II/base/mpi.h>
#include <deal.II/distributed/grid_refinement.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_renumbering.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>

#include <vefs/compat/constraint_distribution.h>
#include <vefs/fields/transported_fields.h>

#include <iostream>

using namespace dealii;

namespace
{
  /** Reproducible values that differ from entry to entry. */
  double
  value_of(const types::global_dof_index index)
  {
    return std::sin(0.37 * index + 0.1) + 0.01 * index;
  }

  template <int dim>
  void
  make_mesh(parallel::distributed::Triangulation<dim> &triangulation)
  {
    Point<dim> lower, upper;
    for (unsigned int d = 0; d < dim; ++d)
      {
        lower[d] = -1;
        upper[d] = 1;
      }
    GridGenerator::subdivided_hyper_rectangle(triangulation,
                                              std::vector<unsigned int>(dim, 2),
                                              lower,
                                              upper,
                                              true);
    // Periodic in x: boundary ids 0 and 1.
    std::vector<GridTools::PeriodicFacePair<
      typename parallel::distributed::Triangulation<dim>::cell_iterator>>
      pairs;
    GridTools::collect_periodic_faces(triangulation, 0, 1, 0, pairs);
    triangulation.add_periodicity(pairs);
    triangulation.refine_global(dim == 2 ? 2 : 1);
    // Two levels more near a corner that touches both periodic walls: the
    // periodic faces and the hanging nodes meet.
    for (unsigned int cycle = 0; cycle < 2; ++cycle)
      {
        for (const auto &cell : triangulation.active_cell_iterators())
          if (cell->is_locally_owned() &&
              cell->center()[1] > 0.3 - 0.4 * cycle &&
              (cell->center()[0] < -0.4 || cell->center()[0] > 0.6))
            cell->set_refine_flag();
        triangulation.execute_coarsening_and_refinement();
      }
  }

  /**
   * Whether every source of every owned constrained entry is in
   * @p available, on all ranks.
   */
  bool
  sources_available(const AffineConstraints<double> &constraints,
                    const IndexSet                  &owned,
                    const IndexSet                  &available,
                    const MPI_Comm                   comm)
  {
    bool all = true;
    for (const auto &line : constraints.get_lines())
      if (owned.is_element(line.index))
        for (const auto &entry : line.entries)
          all = all && available.is_element(entry.first);
    return !Utilities::MPI::logical_or(!all, comm);
  }

  template <int dim>
  void
  check_fields(std::ostream &out)
  {
    const MPI_Comm                            comm = MPI_COMM_WORLD;
    parallel::distributed::Triangulation<dim> triangulation(comm);
    make_mesh(triangulation);
    vefs::TransportedFields<dim> fields(triangulation, true, false, {0});
    fields.setup_dofs();

    using VectorType = typename vefs::TransportedFields<dim>::VectorType;
    VectorType mine, reference;
    fields.initialize_vector(mine);
    for (const auto index : fields.owned_dofs)
      mine(index) = value_of(index);
    mine.update_ghost_values();
    reference = mine;
    fields.distribute_constraints(mine);
    fields.constraints.distribute(reference);

    unsigned int n_different = 0;
    for (const auto index : fields.owned_dofs)
      if (mine(index) != reference(index))
        ++n_different;
    unsigned int n_constrained = 0;
    for (const auto &line : fields.constraints.get_lines())
      if (fields.owned_dofs.is_element(line.index))
        ++n_constrained;

    const std::string name = std::to_string(dim) + "D fields, ";
    out << name << "all sources on the rank: "
        << (sources_available(fields.constraints,
                              fields.owned_dofs,
                              fields.relevant_dofs,
                              comm)
              ? "yes"
              : "no")
        << '\n';
    out << name
        << "constrained entries: " << Utilities::MPI::sum(n_constrained, comm)
        << ", entries different from deal.II: "
        << Utilities::MPI::sum(n_different, comm) << '\n';
  }

  template <int dim>
  void
  check_blocks(std::ostream &out)
  {
    const MPI_Comm                            comm = MPI_COMM_WORLD;
    parallel::distributed::Triangulation<dim> triangulation(comm);
    make_mesh(triangulation);
    // Velocity and pressure, Q1 each, numbered by block.
    const FESystem<dim> fe(FE_Q<dim>(1), dim, FE_Q<dim>(1), 1);
    DoFHandler<dim>     dof_handler(triangulation);
    dof_handler.distribute_dofs(fe);
    std::vector<unsigned int> blocks(dim + 1, 0);
    blocks[dim] = 1;
    DoFRenumbering::component_wise(dof_handler, blocks);
    const auto n_per_block =
      DoFTools::count_dofs_per_fe_block(dof_handler, blocks);
    const IndexSet owned = dof_handler.locally_owned_dofs();
    IndexSet       relevant;
    DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
    const std::vector<IndexSet> owned_blocks = {
      owned.get_view(0, n_per_block[0]),
      owned.get_view(n_per_block[0], n_per_block[0] + n_per_block[1])};
    const std::vector<IndexSet> relevant_blocks = {
      relevant.get_view(0, n_per_block[0]),
      relevant.get_view(n_per_block[0], n_per_block[0] + n_per_block[1])};

    AffineConstraints<double> constraints(relevant);
    DoFTools::make_hanging_node_constraints(dof_handler, constraints);
    DoFTools::make_periodicity_constraints(dof_handler, 0, 1, 0, constraints);
    constraints.close();

    TrilinosWrappers::MPI::BlockVector mine(owned_blocks, comm),
      ghosted(owned_blocks, relevant_blocks, comm);
    for (const auto index : owned)
      mine(index) = value_of(index);
    mine.compress(VectorOperation::insert);
    TrilinosWrappers::MPI::BlockVector reference(mine);
    ghosted = mine;

    vefs::ConstraintDistribution distribution;
    distribution.reinit(constraints, mine, ghosted);
    distribution.distribute(ghosted, mine);
    constraints.distribute(reference);

    unsigned int n_different = 0, n_constrained = 0;
    for (const auto index : owned)
      {
        if (mine(index) != reference(index))
          ++n_different;
        if (constraints.is_constrained(index))
          ++n_constrained;
      }
    const std::string name = std::to_string(dim) + "D blocks, ";
    out << name << "all sources on the rank: "
        << (sources_available(constraints, owned, relevant, comm) ? "yes"
                                                                  : "no")
        << '\n';
    out << name
        << "constrained entries: " << Utilities::MPI::sum(n_constrained, comm)
        << ", entries different from deal.II: "
        << Utilities::MPI::sum(n_different, comm) << '\n';
  }
} // namespace

int
main(int argc, char **argv)
{
  return unit_test::run(argc, argv, [](std::ostream &out) {
    check_fields<2>(out);
    check_fields<3>(out);
    check_blocks<2>(out);
    check_blocks<3>(out);
  });
}
