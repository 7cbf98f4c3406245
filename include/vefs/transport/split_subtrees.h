#ifndef vefs_split_subtrees_h
#define vefs_split_subtrees_h

#include <deal.II/distributed/tria.h>

#include <vefs/fields/transported_fields.h>
#include <vefs/transport/level_set_gradient.h>
#include <vefs/transport/level_set_history.h>

namespace vefs
{
  /**
   * Mend a partition that cuts a subtree of the cells of @p level
   * (SubtreePartition): repartition @p triangulation with its weights and
   * carry @p fields, @p level_set_gradient and the vectors of @p history
   * to the new owners; no cell changes. Does nothing if no subtree is cut.
   * A checkpoint loaded on another number of ranks has p4est's partition,
   * which counts cells and may cut a flow element (measured: written on 2
   * ranks, resumed on 3, test restart_grandparents). Collective.
   */
  template <int dim>
  void
  mend_split_subtrees(parallel::distributed::Triangulation<dim> &triangulation,
                      const int                                  level,
                      TransportedFields<dim>                    &fields,
                      LevelSetGradient<dim> &level_set_gradient,
                      LevelSetHistory<dim>  &history);
} // namespace vefs

#endif
