// make_owned_rows_matrix() (owned_rows_matrix.h, the flow step's matrices)
// against TrilinosWrappers::BlockSparseMatrix::reinit() from the same
// distributed block sparsity pattern (velocity and pressure blocks of a Q1
// system with hanging-node constraints, built as the flow step builds it:
// rows of the relevant unknowns, then distribute_sparsity_pattern()), 2D
// and 3D, 1 and 2 ranks: the same columns in every owned row of every
// block, bit for bit, and the same product with a vector once both are
// filled with the same entries (to 1e-14 relative: the order of the
// entries within a row may differ).

#include "unit_test.h"

#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_renumbering.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>

#include <Epetra_CrsMatrix.h>
#include <vefs/compat/owned_rows_matrix.h>

#include <algorithm>
#include <iostream>

using namespace dealii;

namespace
{
  /** The sorted global columns of the owned @p row of @p matrix. */
  std::vector<long long>
  columns_of(const TrilinosWrappers::SparseMatrix &matrix,
             const types::global_dof_index         row)
  {
    const Epetra_CrsMatrix &epetra = matrix.trilinos_matrix();
    const int               local =
      epetra.RowMap().LID(static_cast<TrilinosWrappers::types::int_type>(row));
    int     n_entries;
    double *values;
    int    *local_columns;
    epetra.ExtractMyRowView(local, n_entries, values, local_columns);
    std::vector<long long> columns(n_entries);
    for (int k = 0; k < n_entries; ++k)
      columns[k] = epetra.ColMap().GID64(local_columns[k]);
    std::sort(columns.begin(), columns.end());
    return columns;
  }

  template <int dim>
  void
  check(std::ostream &out)
  {
    const MPI_Comm                            comm = MPI_COMM_WORLD;
    parallel::distributed::Triangulation<dim> triangulation(comm);
    GridGenerator::hyper_cube(triangulation, 0, 1, true);
    triangulation.refine_global(dim == 2 ? 3 : 2);
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned() && cell->center()[0] < 0.4)
        cell->set_refine_flag();
    triangulation.execute_coarsening_and_refinement();

    const FESystem<dim> fe(FE_Q<dim>(1), dim, FE_Q<dim>(1), 1);
    DoFHandler<dim>     dof_handler(triangulation);
    dof_handler.distribute_dofs(fe);
    std::vector<unsigned int> blocks(dim + 1, 0);
    blocks[dim] = 1;
    DoFRenumbering::component_wise(dof_handler, blocks);
    const auto     n = DoFTools::count_dofs_per_fe_block(dof_handler, blocks);
    const IndexSet owned = dof_handler.locally_owned_dofs();
    IndexSet       relevant;
    DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
    const std::vector<IndexSet> owned_blocks = {owned.get_view(0, n[0]),
                                                owned.get_view(n[0],
                                                               n[0] + n[1])};
    const std::vector<IndexSet> relevant_blocks =
      {relevant.get_view(0, n[0]), relevant.get_view(n[0], n[0] + n[1])};

    AffineConstraints<double> constraints(relevant);
    DoFTools::make_hanging_node_constraints(dof_handler, constraints);
    constraints.close();
    BlockDynamicSparsityPattern pattern(relevant_blocks);
    DoFTools::make_sparsity_pattern(dof_handler, pattern, constraints, false);
    SparsityTools::distribute_sparsity_pattern(pattern, owned, comm, relevant);

    TrilinosWrappers::BlockSparseMatrix mine, theirs;
    vefs::make_owned_rows_matrix(pattern, owned_blocks, comm, mine);
    theirs.reinit(owned_blocks, pattern, comm);

    unsigned int n_rows = 0, n_different_rows = 0;
    for (unsigned int i = 0; i < 2; ++i)
      for (unsigned int j = 0; j < 2; ++j)
        for (const auto row : owned_blocks[i])
          {
            ++n_rows;
            if (columns_of(mine.block(i, j), row) !=
                columns_of(theirs.block(i, j), row))
              ++n_different_rows;
          }

    // The same entries into both, then one product each.
    for (auto *matrix : {&mine, &theirs})
      {
        for (unsigned int i = 0; i < 2; ++i)
          for (unsigned int j = 0; j < 2; ++j)
            for (const auto row : owned_blocks[i])
              for (const long long column : columns_of(theirs.block(i, j), row))
                matrix->block(i, j).set(row,
                                        column,
                                        std::sin(0.3 * row + 0.7 * column) +
                                          (row == column));
        matrix->compress(VectorOperation::insert);
      }
    TrilinosWrappers::MPI::BlockVector x(owned_blocks, comm),
      mine_product(owned_blocks, comm), their_product(owned_blocks, comm);
    for (const auto index : owned)
      x(index) = std::cos(0.11 * index);
    x.compress(VectorOperation::insert);
    mine.vmult(mine_product, x);
    theirs.vmult(their_product, x);
    their_product -= mine_product;

    const std::string name = std::to_string(dim) + "D, ";
    out << name << "owned block rows: " << Utilities::MPI::sum(n_rows, comm)
        << ", with other columns than deal.II's: "
        << Utilities::MPI::sum(n_different_rows, comm) << '\n';
    out << name << "entries: " << mine.n_nonzero_elements()
        << ", deal.II's: " << theirs.n_nonzero_elements() << '\n';
    unit_test::check_below(out,
                           name + "product - deal.II's, relative",
                           their_product.linfty_norm() /
                             mine_product.linfty_norm(),
                           1e-14);
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
