// SubtreePartition (subtree_partition.h) on the unit square and cube:
// level 1, then three rounds of refinement toward the circle (sphere)
// |x| = 0.7 (cells within three diameters of it), so that the level-1 cells
// near it hold subtrees of depth 2 and 3. With the partition's weights
// (each cell 1) and a repartition(), no level-1 cell and no level-2 cell
// has descendants on two ranks (subtrees_split(), and counted directly:
// the owned cells whose subtree's cells are not all owned), and the cells
// are spread over the ranks (each rank owns some). Exact integers: 1, 2
// and 3 ranks print the same; on one rank nothing can split. Without the
// weights (p4est's own partition, measured) 64 and 16 owned cells lie in
// split subtrees of levels 1 and 2 in 2D on 2 ranks, 498 and 64 in 3D, and
// subtrees_split() says yes.

#include "unit_test.h"

#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/grid/grid_generator.h>

#include <vefs/transport/subtree_partition.h>

#include <iostream>
#include <string>
#include <vector>

using namespace dealii;

namespace
{
  /** Whether all active descendants of @p cell are locally owned. */
  template <typename CellIterator>
  bool
  all_owned(const CellIterator &cell)
  {
    if (!cell->has_children())
      return cell->is_locally_owned();
    for (unsigned int c = 0; c < cell->n_children(); ++c)
      if (!all_owned(cell->child(c)))
        return false;
    return true;
  }

  template <int dim>
  void
  check(std::ostream &out, const int level)
  {
    const MPI_Comm                            comm = MPI_COMM_WORLD;
    parallel::distributed::Triangulation<dim> triangulation(
      comm,
      Triangulation<dim>::limit_level_difference_at_vertices,
      parallel::distributed::Triangulation<
        dim>::mesh_reconstruction_after_repartitioning);
    GridGenerator::hyper_cube(triangulation, 0, 1);
    triangulation.refine_global(1);
    vefs::SubtreePartition<dim>(
      level,
      [](const typename Triangulation<dim>::cell_iterator &,
         const typename Triangulation<dim>::CellStatus) { return 1u; })
      .connect_to(triangulation);
    unit_test::refine_toward_circle(triangulation);
    triangulation.repartition();

    unsigned int split_cells = 0;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned() && cell->level() > level)
        {
          auto ancestor = typename Triangulation<dim>::cell_iterator(cell);
          while (ancestor->level() > level)
            ancestor = ancestor->parent();
          split_cells += !all_owned(ancestor);
        }
    const std::string name =
      std::to_string(dim) + "D, level " + std::to_string(level) + ": ";
    out << name << "subtrees_split(): "
        << (vefs::subtrees_split(triangulation, level) ? "yes" : "no") << '\n';
    unit_test::check_zero(out,
                          name + "owned cells of split subtrees",
                          Utilities::MPI::sum(split_cells, comm));
    out << name << "every rank owns cells: "
        << (Utilities::MPI::min(triangulation.n_locally_owned_active_cells(),
                                comm) > 0
              ? "yes"
              : "NO")
        << '\n';
  }
} // namespace

int
main(int argc, char **argv)
{
  return unit_test::run(argc, argv, [](std::ostream &out) {
    check<2>(out, 1);
    check<2>(out, 2);
    check<3>(out, 1);
    check<3>(out, 2);
  });
}
