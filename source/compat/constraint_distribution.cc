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
    this->constraints = &constraints;
    targets.clear();
    inhomogeneities.clear();
    entry_start.assign(1, 0);
    entry_places.clear();
    entry_weights.clear();
    const IndexSet owned_indices = owned.locally_owned_elements();
    complete                     = true;
    for (const auto &line : constraints.get_lines())
      if (owned_indices.is_element(line.index))
        {
          targets.push_back(place_of(owned, line.index));
          inhomogeneities.push_back(line.inhomogeneity);
          for (const auto &[index, weight] : line.entries)
            {
              const Place place = place_of(ghosted, index);
              complete          = complete && place.local_index >= 0;
              entry_places.push_back(place);
              entry_weights.push_back(weight);
            }
          entry_start.push_back(entry_places.size());
        }
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
    for (unsigned int i = 0; i < targets.size(); ++i)
      {
        double value = inhomogeneities[i];
        for (unsigned int e = entry_start[i]; e < entry_start[i + 1]; ++e)
          value += entry_weights[e] *
                   from[entry_places[e].block][entry_places[e].local_index];
        to[targets[i].block][targets[i].local_index] = value;
      }
  }
} // namespace vefs
