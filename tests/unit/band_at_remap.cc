// The cycles that complete the band at a remap (SurfaceTracker::adapt_mesh,
// doc/transport.md, "The band at remaps"): adapt_mesh() once with the
// present band kept, then with PresentBand::refine_only and no
// CoarsenedDetail until the mesh stops changing. On the unit square, levels
// 2 to 6, the mesh adapted to the circle |x - (0.5, 0.3)| = 0.2, the level
// set then replaced by the same circle 0.25 higher (the surface moved
// between remaps, crossing cells as coarse as level L). Exact answers:
// - one change moves a cell by one level, so the cycles stop after
//   max_level - L changes, and then no cell the surface crosses is coarser
//   than the finest;
// - the refine-only cycles coarsen nothing: at the centres of a uniform
//   level-7 lattice (finer than every cell, each centre inside one cell)
//   the level of the cell around it never falls in them, while the first
//   cycle does coarsen the old band somewhere (which shows the lattice sees
//   coarsening).
// 1 and 2 ranks print the same.

#include "circle_band.h"
#include "unit_test.h"

#include <deal.II/base/function.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/grid/grid_generator.h>

#include <vefs/base/cavity.h>
#include <vefs/fields/transported_fields.h>
#include <vefs/transport/level_set_gradient.h>
#include <vefs/transport/mesh_adaptation.h>

#include <algorithm>
#include <iostream>
#include <vector>

using namespace dealii;

namespace
{
  const double       radius        = 0.2;
  const unsigned int lattice_level = 7;

  /**
   * The level of the cell around each centre of the uniform level-7
   * lattice, the same on every rank.
   */
  std::vector<unsigned int>
  levels_at_lattice(const parallel::distributed::Triangulation<2> &mesh)
  {
    const unsigned int        n = 1u << lattice_level;
    std::vector<unsigned int> levels(n * n, 0);
    for (const auto &cell : mesh.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const unsigned int per_side = 1u << (lattice_level - cell->level());
          const unsigned int i0       = std::lround(cell->vertex(0)[0] * n);
          const unsigned int j0       = std::lround(cell->vertex(0)[1] * n);
          for (unsigned int i = i0; i < i0 + per_side; ++i)
            for (unsigned int j = j0; j < j0 + per_side; ++j)
              levels[i * n + j] = cell->level();
        }
    std::vector<unsigned int> on_all_ranks(levels.size());
    Utilities::MPI::sum(levels, mesh.get_communicator(), on_all_ranks);
    return on_all_ranks;
  }

  /** Lattice centres whose cell is coarser in @p after than in @p before. */
  unsigned int
  coarsened_points(const std::vector<unsigned int> &before,
                   const std::vector<unsigned int> &after)
  {
    unsigned int count = 0;
    for (unsigned int k = 0; k < before.size(); ++k)
      count += after[k] < before[k];
    return count;
  }

} // namespace

int
main(int argc, char **argv)
{
  return unit_test::run(argc, argv, [](std::ostream &out) {
    const MPI_Comm                          comm = MPI_COMM_WORLD;
    parallel::distributed::Triangulation<2> mesh(
      comm,
      Triangulation<2>::limit_level_difference_at_vertices);
    GridGenerator::hyper_cube(mesh, 0, 1);
    const vefs::MeshParameters parameters =
      unit_test::circle_band_parameters(vefs::BandPlacement::widened);
    mesh.refine_global(parameters.min_level);
    const vefs::MeshLevels levels = unit_test::unit_square_levels(parameters);

    vefs::TransportedFields<2> fields(mesh, false, false, {});
    fields.setup_dofs();
    vefs::LevelSetGradient<2> gradient;
    const auto                linear = vefs::LevelSetInterpolation::linear;
    const unit_test::CircleDistance present(Point<2>(0.5, 0.3), radius),
      moved(Point<2>(0.5, 0.55), radius);
    unit_test::adapt_to_band(mesh,
                             fields,
                             gradient,
                             parameters,
                             levels,
                             present);
    // The surface moved between remaps: the level set of the moved circle on
    // the present band's mesh.
    fields.interpolate(moved, Functions::ZeroFunction<2>(2));
    const unsigned int coarsest = unit_test::coarsest_cut_level(mesh, moved);

    // The remap's cycles.
    unsigned int changes = 0, coarsened_first = 0, coarsened_later = 0;
    for (; changes < 10; ++changes)
      {
        const auto before = levels_at_lattice(mesh);
        if (!vefs::adapt_mesh(mesh,
                              fields,
                              &gradient,
                              levels,
                              linear,
                              nullptr,
                              changes == 0 ? vefs::PresentBand::kept
                                           : vefs::PresentBand::refine_only))
          break;
        const unsigned int coarsened =
          coarsened_points(before, levels_at_lattice(mesh));
        (changes == 0 ? coarsened_first : coarsened_later) += coarsened;
      }
    const vefs::SurfaceCells surface =
      vefs::count_surface_cells(fields, parameters.max_level);

    out << "coarsest level the moved surface crosses: " << coarsest << '\n'
        << "changes until the mesh stops changing: " << changes
        << " (max_level - that: " << parameters.max_level - coarsest << ")\n"
        << "surface cells coarser than the finest after them: "
        << surface.coarse << '\n'
        << "the first change coarsens the old band: "
        << (coarsened_first > 0 ? "yes" : "no") << '\n'
        << "lattice points whose cell the refine-only changes coarsen: "
        << coarsened_later << '\n';
  });
}
