#include <deal.II/base/mpi.h>

#include <vefs/compat/constraint_distribution.h>

namespace vefs
{
  ConstraintDistribution::Place
  ConstraintDistribution::place_of(const BlockVector            &vector,
                                   const types::global_dof_index index)
  {
    const auto [block, index_in_block] =
      vector.get_block_indices().global_to_local(index);
    const int local_index = vector.block(block).trilinos_vector().Map().LID(
      static_cast<TrilinosWrappers::types::int_type>(index_in_block));
    return {block, local_index};
  }

  void
  ConstraintDistribution::reinit(const AffineConstraints<double> &constraints,
                                 const BlockVector               &owned,
                                 const BlockVector               &ghosted)
  {
    this->constraints            = &constraints;
    const IndexSet owned_indices = owned.locally_owned_elements();
    complete                     = lines.reinit(
      constraints,
      [&](const types::global_dof_index index, Place &place) {
        if (!owned_indices.is_element(index))
          return false;
        place = place_of(owned, index);
        return true;
      },
      [&](const types::global_dof_index index, Place &place) {
        place = place_of(ghosted, index);
        return place.local_index >= 0;
      });
    // The fallback is collective: every rank takes it if one must.
    complete =
      !Utilities::MPI::logical_or(!complete,
                                  owned.block(0).get_mpi_communicator());
  }

  void
  ConstraintDistribution::distribute(const BlockVector &ghosted,
                                     BlockVector       &owned) const
  {
    Assert(constraints, ExcMessage("distribute() after reinit()."));
    if (!complete)
      {
        constraints->distribute(owned);
        return;
      }
    std::vector<const double *> from(ghosted.n_blocks());
    std::vector<double *>       to(owned.n_blocks());
    for (unsigned int b = 0; b < owned.n_blocks(); ++b)
      {
        from[b] = ghosted.block(b).trilinos_vector()[0];
        to[b]   = owned.block(b).trilinos_vector()[0];
      }
    lines.distribute(
      [&](const Place &place) { return from[place.block][place.local_index]; },
      [&](const Place &place, const double value) {
        to[place.block][place.local_index] = value;
      });
  }
} // namespace vefs
