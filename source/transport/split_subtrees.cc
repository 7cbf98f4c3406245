#include <vefs/fields/vertex_field_transfer.h>
#include <vefs/transport/split_subtrees.h>
#include <vefs/transport/subtree_partition.h>

#include <numeric>

namespace vefs
{
  template <int dim>
  void
  mend_split_subtrees(parallel::distributed::Triangulation<dim> &triangulation,
                      const int                                  level,
                      TransportedFields<dim>                    &fields,
                      LevelSetGradient<dim> &level_set_gradient,
                      LevelSetHistory<dim>  &history)
  {
    if (!subtrees_split(triangulation, level))
      return;
    using Transfer   = VertexFieldTransfer<dim>;
    using VectorType = typename TransportedFields<dim>::VectorType;
    // Every vector is laid out like the fields: carry all components.
    std::vector<unsigned int> all_components(fields.n_components);
    std::iota(all_components.begin(), all_components.end(), 0);
    std::vector<typename Transfer::Slot> slots = {
      {&fields.vector(), all_components},
      {&level_set_gradient.vector(), all_components}};
    for (const VectorType *vector : history.vectors())
      slots.push_back({vector, all_components});
    const auto scalars = history.scalars();

    std::vector<VectorType> moved =
      carry_through_mesh_change(triangulation, fields, slots, [&]() {
        triangulation.repartition();
      });
    fields.swap(moved[0]);
    fields.finalize();
    level_set_gradient.reinit(fields);
    level_set_gradient.swap(moved[1]);
    level_set_gradient.finalize(fields);
    const auto kept = history.restore(scalars, fields);
    AssertThrow(kept.size() + 2 == moved.size(), ExcInternalError());
    for (unsigned int i = 0; i < kept.size(); ++i)
      {
        fields.make_consistent(moved[i + 2]);
        kept[i]->swap(moved[i + 2]);
      }
    history.restored();
  }

  template void
  mend_split_subtrees(parallel::distributed::Triangulation<2> &,
                      const int,
                      TransportedFields<2> &,
                      LevelSetGradient<2> &,
                      LevelSetHistory<2> &);
  template void
  mend_split_subtrees(parallel::distributed::Triangulation<3> &,
                      const int,
                      TransportedFields<3> &,
                      LevelSetGradient<3> &,
                      LevelSetHistory<3> &);
} // namespace vefs
