// shadow_holes() (io/shadow_holes.h), the statistics column shadow_holes,
// against exact areas in the cavity [-1, 1]^dim. The liquid's surfaces run
// along mesh lines (multiples of 0.25), so that the cells holding liquid
// are exactly those inside it; the mesh is refined twice more around the
// surface, the second time for x < 0.2 only (hanging nodes, and liquid
// cells of three sizes on the raster). With s = max |x_d| over the
// horizontal coordinates:
// - a square ring 0.25 <= s <= 0.75 standing on the floor, the whole
//   height (2D: two walls): the hole is s < 0.25, area 0.25 (2D: 0.5);
// - the ring cut open by a channel |y| < 0.25, x > 0 (2D: the left wall
//   only): the hole reaches the floor's edge, 0;
// - the ring with a lid z > 0.75 over s < 0.5: dry floor under liquid, 0;
// - a block s < 0.5 lifted off the floor (0.25 < z < 0.5): 0;
// - no liquid: 0.
// The results must be exact (the raster cells are whole cells); printed
// with 12 digits. 1 and 2 ranks (each rank draws its cells).

#include "unit_test.h"

#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>

#include <vefs/io/shadow_holes.h>

#include <iostream>

using namespace dealii;

namespace
{
  template <int dim>
  double
  holes_of(const std::function<double(const Point<dim> &)> &psi)
  {
    vefs::CavityParameters cavity;
    cavity.cavity_lower = std::vector<double>(dim, -1.);
    cavity.cavity_upper = std::vector<double>(dim, 1.);
    parallel::distributed::Triangulation<dim> triangulation(MPI_COMM_WORLD);
    unit_test::make_box_refined_around(triangulation, psi);
    vefs::TransportedFields<dim> fields(triangulation, false, false, {});
    fields.setup_dofs();
    fields.interpolate(ScalarFunctionFromFunctionObject<dim>(psi),
                       Functions::ZeroFunction<dim>(dim));
    return vefs::shadow_holes(fields, cavity);
  }

  template <int dim>
  void
  check(std::ostream &out)
  {
    const unsigned int vertical = dim - 1;
    const auto         s        = [](const Point<dim> &p) {
      double size = 0;
      for (unsigned int d = 0; d < vertical; ++d)
        size = std::max(size, std::abs(p[d]));
      return size;
    };
    // Negative in the liquid; the union of two liquids is the minimum.
    const std::function<double(const Point<dim> &)> ring =
      [&](const Point<dim> &p) { return std::max(s(p) - 0.75, 0.25 - s(p)); };
    const std::function<double(const Point<dim> &)> open_ring =
      [&](const Point<dim> &p) {
        const double channel =
          dim == 2 ? -p[0] : std::max(-p[0], std::abs(p[1]) - 0.25);
        return std::max(ring(p), -channel);
      };
    const std::function<double(const Point<dim> &)> ring_with_lid =
      [&](const Point<dim> &p) {
        return std::min(ring(p), std::max(0.75 - p[vertical], s(p) - 0.5));
      };
    const std::function<double(const Point<dim> &)> lifted_block =
      [&](const Point<dim> &p) {
        return std::max(s(p) - 0.5, std::abs(p[vertical] - 0.375) - 0.125);
      };
    const std::function<double(const Point<dim> &)> dry =
      [](const Point<dim> &) { return 1.; };

    const std::string name = std::to_string(dim) + "D ";
    out << std::setprecision(12);
    out << name << "square ring (exact " << (dim == 2 ? 0.5 : 0.25)
        << "): " << holes_of(ring) << '\n';
    out << name << "ring open to the edge: " << holes_of(open_ring) << '\n';
    out << name << "ring with a lid: " << holes_of(ring_with_lid) << '\n';
    out << name << "block lifted off the floor: " << holes_of(lifted_block)
        << '\n';
    out << name << "no liquid: " << holes_of(dry) << '\n';
  }
} // namespace

int
main(int argc, char **argv)
{
  return unit_test::run(argc, argv, [](std::ostream &out) {
    check<2>(out);
    check<3>(out);
  });
}
