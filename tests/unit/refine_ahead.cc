// refine_ahead_of_surface() (transport/mesh_adaptation.h) and its stopping
// rule, 'Band miss tolerance': on the unit square, levels 2 to 6, the mesh
// first adapted to the circle |x - (0.5, 0.3)| = 0.2 (the present surface,
// a signed distance), the predicted surface the same circle 0.25 higher,
// crossing cells as coarse as level L. One mesh change refines a cell by
// one level, so that (exact answers):
// - with tolerance 0 the refinement ahead takes max_level - L changes,
//   after which no cell the predicted surface crosses is coarser than the
//   finest;
// - with tolerance 1 it stops after the first change;
// - with a tolerance f between the fractions r_1 > r_2 of coarse predicted
//   cut cells left after 1 and 2 changes (measured here with at most 1 and 2
//   cycles), it stops after 2 changes: the first change after which at most
//   the fraction f is left.
// Each run starts from the same mesh, in the scenes' mode: the first change
// also coarsens the present band. 1 and 2 ranks print the same.

#include "circle_band.h"
#include "unit_test.h"

#include <deal.II/base/function.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/grid/grid_generator.h>

#include <vefs/base/cavity.h>
#include <vefs/fields/coarsened_detail.h>
#include <vefs/fields/transported_fields.h>
#include <vefs/transport/level_set_gradient.h>
#include <vefs/transport/mesh_adaptation.h>

#include <algorithm>
#include <iostream>
#include <vector>

using namespace dealii;

namespace
{
  const Point<2> present_centre(0.5, 0.3);
  const Point<2> ahead_centre(0.5, 0.55);
  const double   radius = 0.2;

  vefs::MeshParameters
  mesh_parameters()
  {
    return unit_test::circle_band_parameters(
      vefs::BandPlacement::predicted_one_change);
  }

  struct Outcome
  {
    /** The coarsest level of a cell the predicted surface crosses before. */
    unsigned int       coarsest_level;
    unsigned int       changes;
    vefs::SurfaceCells ahead;
  };

  /**
   * From the mesh adapted to the present circle, the refinement ahead of the
   * predicted one with at most @p max_cycles changes and @p miss_tolerance.
   */
  Outcome
  refine_ahead(const unsigned int max_cycles, const double miss_tolerance)
  {
    const MPI_Comm                          comm = MPI_COMM_WORLD;
    parallel::distributed::Triangulation<2> triangulation(
      comm,
      Triangulation<2>::limit_level_difference_at_vertices);
    GridGenerator::hyper_cube(triangulation, 0, 1);
    const vefs::MeshParameters parameters = mesh_parameters();
    triangulation.refine_global(parameters.min_level);
    const vefs::MeshLevels levels = unit_test::unit_square_levels(parameters);

    vefs::TransportedFields<2> fields(triangulation, false, false, {});
    fields.setup_dofs();
    vefs::LevelSetGradient<2>       gradient;
    const unit_test::CircleDistance present(present_centre, radius),
      ahead(ahead_centre, radius);
    unit_test::adapt_to_band(triangulation,
                             fields,
                             gradient,
                             parameters,
                             levels,
                             present);
    // The predicted surface's level set on the mesh of the present band.
    const Functions::ZeroFunction<2> velocity(2);
    fields.interpolate(ahead, velocity);
    vefs::TransportedFields<2>::VectorType surface_ahead = fields.vector();
    fields.interpolate(present, velocity);

    vefs::CoarsenedDetail<2> coarsened_detail;
    Outcome                  outcome;
    outcome.coarsest_level =
      unit_test::coarsest_cut_level(triangulation, ahead);
    outcome.changes =
      vefs::refine_ahead_of_surface(triangulation,
                                    fields,
                                    gradient,
                                    levels,
                                    max_cycles,
                                    vefs::LevelSetInterpolation::linear,
                                    surface_ahead,
                                    true,
                                    miss_tolerance,
                                    coarsened_detail);
    outcome.ahead =
      vefs::count_surface_cells(fields, surface_ahead, parameters.max_level);
    return outcome;
  }

  double
  coarse_fraction(const vefs::SurfaceCells &cells)
  {
    return static_cast<double>(cells.coarse) / cells.total;
  }
} // namespace

int
main(int argc, char **argv)
{
  return unit_test::run(argc, argv, [](std::ostream &out) {
    const unsigned int all_cycles = 10;

    const Outcome exact = refine_ahead(all_cycles, 0);
    out << "coarsest level the predicted surface crosses: "
        << exact.coarsest_level << '\n'
        << "tolerance 0: changes: " << exact.changes << " (max_level - that: "
        << mesh_parameters().max_level - exact.coarsest_level
        << "), predicted cut cells coarser than the finest: "
        << exact.ahead.coarse << '\n';

    const Outcome one = refine_ahead(all_cycles, 1);
    out << "tolerance 1: changes: " << one.changes << '\n';

    const double r_1 = coarse_fraction(refine_ahead(1, 0).ahead);
    const double r_2 = coarse_fraction(refine_ahead(2, 0).ahead);
    if (std::getenv("VEFS_UNIT_VERBOSE"))
      std::cerr << "r_1 = " << r_1 << ", r_2 = " << r_2 << '\n';
    out << "coarse fraction falls from the first change to the second: "
        << (r_2 < r_1 ? "yes" : "no") << '\n';
    const double  between = 0.5 * (r_1 + r_2);
    const Outcome two     = refine_ahead(all_cycles, between);
    out << "tolerance between them: changes: " << two.changes
        << ", left within the tolerance: "
        << (two.ahead.within(between) ? "yes" : "no") << '\n';
  });
}
