#ifndef vefs_constraint_distribution_h
#define vefs_constraint_distribution_h

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>

#include <vefs/compat/local_constraint_lines.h>

namespace vefs
{
  using namespace dealii;

  /**
   * AffineConstraints::distribute() for the flow's Trilinos block vectors,
   * by local indices worked out once per set of constraints. deal.II's
   * builds a ghosted copy with a new Epetra map and looks every entry up
   * by its global index on each call: with the flow on the parents, whose
   * children's unknowns are all constrained, that took a fifth of the
   * Stokes solves' time (3D ball at 2.5 mm, after every contact
   * iteration).
   */
  class ConstraintDistribution
  {
  public:
    using BlockVector = TrilinosWrappers::MPI::BlockVector;

    /**
     * Look up the places of the owned constrained unknowns of
     * @p constraints (closed) in vectors of the layout of @p owned, and
     * those of the unknowns they depend on in vectors of the layout of
     * @p ghosted. If @p ghosted lacks one of those on any rank,
     * distribute() falls back to deal.II's on every rank (it is
     * collective). Collective.
     */
    void
    reinit(const AffineConstraints<double> &constraints,
           const BlockVector               &owned,
           const BlockVector               &ghosted);

    /**
     * Set the owned constrained entries of @p owned from the values of
     * @p ghosted, which holds those of @p owned (ghosts updated) but for
     * the constrained entries, which it does not read.
     */
    void
    distribute(const BlockVector &ghosted, BlockVector &owned) const;

  private:
    /** An entry of a block vector: its block and index on this rank. */
    struct Place
    {
      unsigned int block;
      int          local_index;
    };

    /** Where a block vector's global index @p index lies, -1 if not here. */
    static Place
    place_of(const BlockVector &vector, const types::global_dof_index index);

    const AffineConstraints<double> *constraints = nullptr;
    bool                             complete    = false;
    LocalConstraintLines<Place>      lines;
  };
} // namespace vefs

#endif
