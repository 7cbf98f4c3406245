#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <Epetra_CrsGraph.h>
#include <Epetra_CrsMatrix.h>
#include <Epetra_Map.h>
#include <vefs/compat/owned_rows_matrix.h>

namespace vefs
{
  /**
   * Make @p matrix a block matrix of the entries of @p pattern in the rows
   * this rank owns, after SparsityTools::distribute_sparsity_pattern() has
   * added the other ranks' entries to them: each block an Epetra graph
   * filled row by row. Given the ghost rows as well, deal.II would build
   * Epetra maps of them and a second graph for the entries that the
   * assembly adds to other ranks' rows; copying the owned rows into a
   * second pattern for deal.II cost two ranks 6 % of the setup. Without
   * the ghost rows, Epetra sends those entries itself when the matrix is
   * compressed.
   */
  void
  make_owned_rows_matrix(const BlockDynamicSparsityPattern &pattern,
                         const std::vector<IndexSet>       &owned_partitioning,
                         const MPI_Comm                     comm,
                         TrilinosWrappers::BlockSparseMatrix &matrix)
  {
    using EpetraIndex         = TrilinosWrappers::types::int_type;
    const unsigned int      n = owned_partitioning.size();
    std::vector<Epetra_Map> maps;
    for (const IndexSet &owned : owned_partitioning)
      maps.push_back(owned.make_trilinos_map(comm, false));
    matrix.clear();
    matrix.reinit(n, n);
    std::vector<int>         lengths;
    std::vector<EpetraIndex> columns;
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        {
          const DynamicSparsityPattern &block = pattern.block(i, j);
          lengths.clear();
          for (const types::global_dof_index row : owned_partitioning[i])
            lengths.push_back(block.row_length(row));
          Epetra_CrsGraph graph(Copy, maps[i], lengths.data(), true);
          unsigned int    k = 0;
          for (const types::global_dof_index row : owned_partitioning[i])
            {
              const int length = lengths[k++];
              if (length == 0)
                continue;
              // Counted: the pattern's end(row) searches for the next row.
              columns.resize(length);
              auto entry = block.begin(row);
              for (int c = 0; c < length; ++c, ++entry)
                columns[c] = entry->column();
              graph.InsertGlobalIndices(static_cast<EpetraIndex>(row),
                                        length,
                                        columns.data());
            }
          graph.FillComplete(maps[j], maps[i]);
          graph.OptimizeStorage();
          matrix.block(i, j).reinit(Epetra_CrsMatrix(Copy, graph), false);
        }
    matrix.collect_sizes();
  }
} // namespace vefs
