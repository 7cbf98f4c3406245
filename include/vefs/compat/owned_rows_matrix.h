#ifndef vefs_owned_rows_matrix_h
#define vefs_owned_rows_matrix_h

#include <deal.II/base/index_set.h>
#include <deal.II/lac/block_sparsity_pattern.h>
#include <deal.II/lac/trilinos_block_sparse_matrix.h>

#include <vector>

namespace vefs
{
  using namespace dealii;

  /**
   * Make @p matrix a block matrix of the entries of @p pattern in the rows
   * this rank owns (@p owned_partitioning, by block), after
   * SparsityTools::distribute_sparsity_pattern() has added the other ranks'
   * entries to them: the flow step's matrices. Replaces
   * TrilinosWrappers::BlockSparseMatrix::reinit() from the pattern with its
   * ghost rows, which builds Epetra maps of the ghost rows and a second
   * graph for the entries the assembly adds to other ranks' rows (copying
   * the owned rows into a second pattern for deal.II cost two ranks 6 % of
   * the flow's setup of the 3D ball at 2.5 mm: commit cbc5f53).
   */
  void
  make_owned_rows_matrix(const BlockDynamicSparsityPattern &pattern,
                         const std::vector<IndexSet>       &owned_partitioning,
                         const MPI_Comm                     comm,
                         TrilinosWrappers::BlockSparseMatrix &matrix);
} // namespace vefs

#endif
