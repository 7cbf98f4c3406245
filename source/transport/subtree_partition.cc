#include <deal.II/base/mpi.h>

#include <vefs/transport/subtree_partition.h>

namespace vefs
{
  namespace
  {
    /** Whether @p cell is the last cell of its ancestor on @p level, or
     * an ancestor of that cell. */
    template <typename CellIterator>
    bool
    on_last_path(const CellIterator &cell, const int level)
    {
      for (CellIterator c = cell; c->level() > level; c = c->parent())
        if (c->parent()->child_iterator_to_index(c) !=
            c->parent()->n_children() - 1)
          return false;
      return true;
    }
  } // namespace

  template <int dim>
  SubtreePartition<dim>::SubtreePartition(const int         level,
                                          const CellWeight &cell_weight)
    : level(level)
    , cell_weight(cell_weight)
  {
  }


  template <int dim>
  unsigned int
  SubtreePartition<dim>::weight(const CellIterator &cell,
                                const CellStatus    status) const
  {
    if (level < 0 || cell->level() < level ||
        (cell->level() == level && !cell->has_children() &&
         status != Triangulation<dim>::CELL_REFINE))
      return cell_weight(cell, status);
    if (!on_last_path(cell, level))
      return 0;
    // The last cell carries its subtree's weight: the cells as they are.
    CellIterator root = cell;
    while (root->level() > level)
      root = root->parent();
    unsigned int              total   = 0;
    std::vector<CellIterator> pending = {root};
    while (!pending.empty())
      {
        const CellIterator c = pending.back();
        pending.pop_back();
        if (c->has_children())
          for (unsigned int i = 0; i < c->n_children(); ++i)
            pending.push_back(c->child(i));
        else
          total += cell_weight(c, Triangulation<dim>::CELL_PERSIST);
      }
    return total;
  }

  template <int dim>
  void
  SubtreePartition<dim>::connect_to(
    parallel::distributed::Triangulation<dim> &triangulation) const
  {
    triangulation.signals.weight.connect(
      [partition = *this](const CellIterator &cell, const CellStatus status) {
        return partition.weight(cell, status);
      });
  }

  template <int dim>
  bool
  subtrees_split(const parallel::distributed::Triangulation<dim> &triangulation,
                 const int                                        level)
  {
    using CellIterator = typename Triangulation<dim>::cell_iterator;
    if (level < 0)
      return false;
    bool split = false;
    // A rank that owns a cell of a split subtree but not its last cell
    // finds it.
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned() && cell->level() > level)
        {
          CellIterator last = cell;
          while (last->level() > level)
            last = last->parent();
          while (last->has_children())
            last = last->child(last->n_children() - 1);
          split = split || !last->is_locally_owned();
        }
    return Utilities::MPI::logical_or(split, triangulation.get_communicator());
  }

  template class SubtreePartition<2>;
  template class SubtreePartition<3>;
  template bool
  subtrees_split(const parallel::distributed::Triangulation<2> &, const int);
  template bool
  subtrees_split(const parallel::distributed::Triangulation<3> &, const int);
} // namespace vefs
