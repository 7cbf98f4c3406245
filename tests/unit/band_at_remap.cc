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

  /** A circle's signed distance, negative inside (in the liquid). */
  class Circle : public Function<2>
  {
  public:
    explicit Circle(const Point<2> &centre)
      : centre(centre)
    {
    }
    double
    value(const Point<2> &p, const unsigned int) const override
    {
      return p.distance(centre) - radius;
    }

  private:
    const Point<2> centre;
  };

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

  /** The lowest level of the cells that @p circle crosses. */
  unsigned int
  coarsest_cut_level(const Triangulation<2> &mesh, const Function<2> &circle)
  {
    unsigned int coarsest = numbers::invalid_unsigned_int;
    for (const auto &cell : mesh.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          bool inside = false, outside = false;
          for (const unsigned int v : cell->vertex_indices())
            (circle.value(cell->vertex(v)) < 0 ? inside : outside) = true;
          if (inside && outside)
            coarsest =
              std::min(coarsest, static_cast<unsigned int>(cell->level()));
        }
    return Utilities::MPI::min(coarsest, MPI_COMM_WORLD);
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
    vefs::MeshParameters parameters;
    parameters.min_level            = 2;
    parameters.bulk_level           = 2;
    parameters.max_level            = 6;
    parameters.band_width           = 2;
    parameters.automatic_band_width = false;
    parameters.band_placement       = vefs::BandPlacement::widened;
    mesh.refine_global(parameters.min_level);
    vefs::CavityParameters cavity;
    cavity.cavity_lower        = {0, 0};
    cavity.cavity_upper        = {1, 1};
    cavity.coarse_subdivisions = {1, 1};
    const vefs::MeshLevels levels(parameters, cavity, 2, 1.);

    vefs::TransportedFields<2> fields(mesh, false, false, {});
    fields.setup_dofs();
    const Functions::ZeroFunction<2> velocity(2);
    vefs::LevelSetGradient<2>        gradient;
    const auto   linear = vefs::LevelSetInterpolation::linear;
    const Circle present(Point<2>(0.5, 0.3)), moved(Point<2>(0.5, 0.55));
    // The band of the present circle: a change refines by one level.
    for (unsigned int cycle = 0;
         cycle < parameters.max_level - parameters.min_level;
         ++cycle)
      {
        fields.interpolate(present, velocity);
        gradient.reinit(fields);
        vefs::adapt_mesh(mesh, fields, &gradient, levels, linear);
      }
    fields.interpolate(moved, velocity);
    gradient.reinit(fields);
    const unsigned int coarsest = coarsest_cut_level(mesh, moved);

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
