// correct_volume() (volume_correction.h): one constant added to the level set
// so that the sharp liquid volume of the flow step (sharp_liquid_volume())
// is the target. Uniform meshes of the unit square (cube), h = 1/32 (1/16
// in 3D), 1 and 2 ranks.
// - A plane, psi = x_last - 0.4, target the volume below x_last = 0.45: the
//   Q1 level set is exact and its volume linear in the shift, so the
//   shift is -0.05 and the volume the target, both to round-off (1e-12).
// - A circle (sphere) as a distance, psi = r - 0.3, target pi 0.31^2
//   (4/3 pi 0.31^3): the volume is the target to 1e-12 of it; the shift is
//   -0.01 up to the Q1 interpolation error of the distance, which moves the
//   surface by at most dim h^2 / (8 R) (second derivatives of r at most
//   1/R near it), at both radii: bound dim h^2 / (4 R).
// - An inflection at the surface, psi = (x_last - 1/2)^3 - 1/1000, target
//   the volume below x_last = 1/2, a plane of vertices: the volume is steep
//   in the shift near the root and flat away from it, like a cube root,
//   where Newton's method alone alternates across the root with growing
//   steps. The shift is 1/1000 and the volume the target to round-off.
// - ShiftWeight::surface_speed on the plane with u = (x_0, 0(, 0)): the
//   weights are w = max(x_0, 0.05) at the nodes (the fastest cut-cell
//   vertex moves at 1), the corrected Q1 surface x_last = 0.4 - c w_h(x_0)
//   is linear in each cell, so its volume 0.4 - c int w_h is exact and c =
//   -0.05 / int w_h (trapezoidal sum of the nodal weights); the nodes at
//   x_0 = 0 move by 0.05 c. With u = 0 the shift is uniform (-0.05).

#include "unit_test.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/numbers.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/grid/grid_generator.h>

#include <vefs/transport/liquid_domain.h>
#include <vefs/transport/volume_correction.h>

#include <cmath>
#include <functional>
#include <iostream>

using namespace dealii;

namespace
{
  template <int dim>
  void
  check(std::ostream                                   &out,
        const std::string                              &name,
        const std::function<double(const Point<dim> &)> level_set,
        const double                                    target,
        const double                                    exact_shift,
        const double                                    shift_bound)
  {
    const MPI_Comm                            comm = MPI_COMM_WORLD;
    parallel::distributed::Triangulation<dim> triangulation(comm);
    GridGenerator::hyper_cube(triangulation, 0, 1);
    triangulation.refine_global(dim == 2 ? 5 : 4);

    vefs::TransportedFields<dim> fields(triangulation, false, false, {});
    fields.setup_dofs();
    for (const auto &node : fields.nodes())
      fields.set_level_set(node, level_set(node.point));
    fields.finalize();

    const double shift  = vefs::correct_volume(fields, target);
    const double volume = vefs::sharp_liquid_volume(fields, 0.).volume;

    const std::string label = std::to_string(dim) + "D, " + name + ", ";
    unit_test::check_below(out,
                           label + "volume error over the target",
                           std::abs(volume - target) / target,
                           1e-12);
    unit_test::check_below(out,
                           label + "shift error",
                           std::abs(shift - exact_shift),
                           shift_bound);
  }

  template <int dim>
  void
  check_surface_speed(std::ostream &out, const double speed)
  {
    const MPI_Comm                            comm = MPI_COMM_WORLD;
    parallel::distributed::Triangulation<dim> triangulation(comm);
    GridGenerator::hyper_cube(triangulation, 0, 1);
    const unsigned int n_cells = dim == 2 ? 32 : 16;
    triangulation.refine_global(dim == 2 ? 5 : 4);

    vefs::TransportedFields<dim> fields(triangulation, false, false, {});
    fields.setup_dofs();
    for (const auto &node : fields.nodes())
      {
        fields.set_level_set(node, node.point[dim - 1] - 0.4);
        Tensor<1, dim> u;
        u[0] = speed * node.point[0];
        fields.set_velocity(node, u);
      }
    fields.finalize();

    const auto weight = [&](const double x) {
      return speed > 0 ? std::max(x, vefs::min_speed_weight) : 1.;
    };
    double integral = 0;
    for (unsigned int i = 0; i < n_cells; ++i)
      integral +=
        0.5 * (weight(double(i) / n_cells) + weight(double(i + 1) / n_cells)) /
        n_cells;
    const double exact_shift = -0.05 / integral;

    const double shift =
      vefs::correct_volume(fields, 0.45, vefs::ShiftWeight::surface_speed);
    const double volume = vefs::sharp_liquid_volume(fields, 0.).volume;
    double       largest_rest_error = 0;
    for (const auto &node : fields.nodes())
      if (node.point[0] == 0)
        largest_rest_error = std::max(largest_rest_error,
                                      std::abs(fields.level_set(node) -
                                               (node.point[dim - 1] - 0.4 +
                                                exact_shift * weight(0))));
    largest_rest_error = Utilities::MPI::max(largest_rest_error, comm);

    const std::string label =
      std::to_string(dim) +
      "D, plane, surface speed weights, u = " + (speed > 0 ? "(x_0, 0)" : "0") +
      ", ";
    unit_test::check_below(out,
                           label + "volume error over the target",
                           std::abs(volume - 0.45) / 0.45,
                           1e-12);
    unit_test::check_below(out,
                           label + "shift error",
                           std::abs(shift - exact_shift),
                           1e-12);
    unit_test::check_below(out,
                           label + "level set error at x_0 = 0",
                           largest_rest_error,
                           1e-12);
  }
} // namespace

int
main(int argc, char **argv)
{
  return unit_test::run(argc, argv, [](std::ostream &out) {
    const double R = 0.3, R_target = 0.31;
    check<2>(
      out,
      "plane",
      [](const Point<2> &p) { return p[1] - 0.4; },
      0.45,
      -0.05,
      1e-12);
    check<3>(
      out,
      "plane",
      [](const Point<3> &p) { return p[2] - 0.4; },
      0.45,
      -0.05,
      1e-12);
    const double h2 = 1. / 32, h3 = 1. / 16;
    check<2>(
      out,
      "circle",
      [=](const Point<2> &p) { return p.distance(Point<2>(0.5, 0.5)) - R; },
      numbers::PI * R_target * R_target,
      R - R_target,
      2 * h2 * h2 / (4 * R));
    check<3>(
      out,
      "sphere",
      [=](const Point<3> &p) {
        return p.distance(Point<3>(0.5, 0.5, 0.5)) - R;
      },
      4. / 3 * numbers::PI * std::pow(R_target, 3),
      R - R_target,
      3 * h3 * h3 / (4 * R));
    const double a = 1e-3;
    check<2>(
      out,
      "inflection",
      [=](const Point<2> &p) { return std::pow(p[1] - 0.5, 3) - a; },
      0.5,
      a,
      1e-12);
    check<3>(
      out,
      "inflection",
      [=](const Point<3> &p) { return std::pow(p[2] - 0.5, 3) - a; },
      0.5,
      a,
      1e-12);
    for (const double speed : {1., 0.})
      {
        check_surface_speed<2>(out, speed);
        check_surface_speed<3>(out, speed);
      }
  });
}
