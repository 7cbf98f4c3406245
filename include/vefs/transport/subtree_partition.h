#ifndef vefs_subtree_partition_h
#define vefs_subtree_partition_h

#include <deal.II/distributed/tria.h>

#include <functional>

namespace vefs
{
  using namespace dealii;

  /**
   * A partition of the mesh that keeps each cell of a given level together
   * with all its descendants on one rank: the flow's elements coarser than
   * the finest cells by two levels or more (FlowElements) need their cells
   * there. p4est keeps only the children of a family of active cells
   * together. It cuts its space-filling curve where the summed weights reach
   * a rank's share; with the whole weight of a subtree on its last active
   * cell and zero on the others, no cut falls inside a subtree (measured:
   * doc/time_step_flow.md). A mesh change that refines such a last cell
   * gives its children one weight each, and may split a subtree:
   * subtrees_split() says so, and a repartition(), where no cell changes,
   * mends it.
   */
  template <int dim>
  class SubtreePartition
  {
  public:
    using CellIterator = typename Triangulation<dim>::cell_iterator;
    using CellStatus   = typename Triangulation<dim>::CellStatus;
    /** The weight of a cell that the partition balances. */
    using CellWeight =
      std::function<unsigned int(const CellIterator &, const CellStatus)>;

    /** Subtrees of the cells of @p level (no subtrees kept if negative). */
    SubtreePartition(const int level, const CellWeight &cell_weight);

    /** What p4est weighs @p cell with (Triangulation::Signals::weight). */
    unsigned int
    weight(const CellIterator &cell, const CellStatus status) const;

    /** Give @p triangulation's partition these weights (a copy of this
     * object is kept in its signal). */
    void
    connect_to(parallel::distributed::Triangulation<dim> &triangulation) const;

  private:
    const int        level;
    const CellWeight cell_weight;
  };

  /** Whether a cell of @p level and its descendants lie on several ranks.
   * Collective. */
  template <int dim>
  bool
  subtrees_split(const parallel::distributed::Triangulation<dim> &triangulation,
                 const int                                        level);
} // namespace vefs

#endif
