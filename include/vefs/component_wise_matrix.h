#ifndef vefs_component_wise_matrix_h
#define vefs_component_wise_matrix_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <Epetra_CrsMatrix.h>

#include <memory>

namespace vefs
{
  using namespace dealii;

  /**
   * The vector component of each velocity unknown in @p touched (owned and
   * read by this rank), 0 to dim - 1: owned entries from the rank's cells
   * with the element @p liquid_index, the others from their owners.
   */
  template <int dim>
  TrilinosWrappers::MPI::Vector
  velocity_components(const DoFHandler<dim> &dof_handler,
                      const unsigned int     liquid_index,
                      const IndexSet        &owned,
                      const IndexSet        &touched);

  /**
   * The entries of the velocity block @p matrix that couple two unknowns
   * of the same vector component (@p components as velocity_components()
   * gives them): for a viscous or elastic block, dim Laplacian-like blocks
   * without the couplings of the symmetric gradient between components,
   * about a third of the entries in 3D. An AMG of it is a cheaper
   * preconditioner of the whole block (Korn's inequality makes the two
   * spectrally equivalent); entries whose column has no known component
   * are kept.
   */
  std::unique_ptr<Epetra_CrsMatrix>
  component_wise_part(const TrilinosWrappers::SparseMatrix &matrix,
                      const TrilinosWrappers::MPI::Vector  &components);
} // namespace vefs

#endif
