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
   * entries to them: the flow step's matrices (stokes_step.cc, where the
   * reasons are given).
   */
  void
  make_owned_rows_matrix(const BlockDynamicSparsityPattern &pattern,
                         const std::vector<IndexSet>       &owned_partitioning,
                         const MPI_Comm                     comm,
                         TrilinosWrappers::BlockSparseMatrix &matrix);
} // namespace vefs

#endif
