// redistance() (redistancing.h) against the signed distance to a circle
// (2D) and a sphere (3D) of radius R = 0.3: the level set starts as
// (r^2 - R^2) / (2R), whose zero set is the circle but which is no
// distance (it is R/2 too small at r = 0 and grows like r^2), with its
// exact gradient for the gradient-augmented transport. Uniform meshes of
// cell size h (1/32 in 2D, 1/16 in 3D), 1 and 2 ranks (the crossings are
// gathered from all ranks, so the result does not depend on the partition).
// - Nodes within h/4 of the surface are vertices of cut cells: their values
//   stay as they were, to round-off (the zero set and the volume do not
//   move).
// - The kept nodes lie within sqrt(dim) h of the surface (vertices of cut
//   cells), with the cubic level set within 2 sqrt(dim) h (and of the cells
//   around those). The nodes farther away hold the signed distance r - R:
//   every surface point has a crossing within t = sqrt(dim) h / 4 (the
//   crossings lie on the edges of a lattice of h/4), so the distance to the
//   nearest crossing exceeds the one to the surface by at most t^2 / (2 d),
//   d the node's distance. The linear level set's crossings are those of
//   its Q1 interpolant, off the surface by up to dim h^2 / (8 R) (second
//   derivatives 1/R): added to the bound.
// - Their level set gradient (cubic) is the surface normal at the nearest
//   crossing, which is the one at the smallest angle from the node seen from
//   the centre: off the radial direction by at most t / R.
// - No node changes sign.
// - With a kept distance of 4h (the remap distance's reach, 2D, gradient
//   augmented), the nodes within 3.5h of the surface keep their values to
//   round-off (the nearest crossing is at most t farther than the surface),
//   those beyond 4h hold r - R within the bound above.

#include "unit_test.h"

#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/grid/grid_generator.h>

#include <vefs/transport/redistancing.h>

#include <cmath>
#include <iostream>

using namespace dealii;

namespace
{
  template <int dim>
  void
  check(std::ostream                     &out,
        const vefs::LevelSetInterpolation interpolation,
        const unsigned int                kept_cells = 0)
  {
    const MPI_Comm                            comm = MPI_COMM_WORLD;
    parallel::distributed::Triangulation<dim> triangulation(comm);
    GridGenerator::hyper_cube(triangulation, 0, 1);
    const unsigned int level = dim == 2 ? 5 : 4;
    triangulation.refine_global(level);
    const double h = 1. / (1u << level);

    const double R = 0.3;
    Point<dim>   center;
    for (unsigned int d = 0; d < dim; ++d)
      center[d] = 0.5;

    vefs::TransportedFields<dim> fields(triangulation, false, false, {});
    fields.setup_dofs();
    vefs::LevelSetGradient<dim> level_set_gradient;
    level_set_gradient.reinit(fields);
    for (const auto &node : fields.nodes())
      {
        const Tensor<1, dim> offset = node.point - center;
        fields.set_level_set(node, (offset.norm_square() - R * R) / (2 * R));
        level_set_gradient.set(node, offset / R);
      }
    fields.finalize();
    level_set_gradient.finalize(fields);

    vefs::redistance(fields, level_set_gradient, interpolation, kept_cells * h);

    const bool   cubic = interpolation != vefs::LevelSetInterpolation::linear;
    const double far =
      std::max<double>((cubic ? 2 : 1) * std::sqrt(dim) * h, kept_cells * h);
    const double near        = std::max(h / 4, (kept_cells - 0.5) * h);
    const double t           = std::sqrt(dim) * h / 4;
    double       near_change = 0, distance_error = 0, gradient_error = 0;
    unsigned int sign_changes = 0, far_nodes = 0;
    for (const auto &node : fields.nodes())
      {
        const Tensor<1, dim> offset   = node.point - center;
        const double         r        = offset.norm();
        const double         start    = (r * r - R * R) / (2 * R);
        const double         value    = fields.level_set(node);
        const double         distance = r - R;
        if ((value < 0) != (start < 0))
          ++sign_changes;
        if (std::abs(distance) < near)
          near_change = std::max(near_change, std::abs(value - start));
        if (std::abs(distance) > far && r > 0)
          {
            ++far_nodes;
            distance_error =
              std::max(distance_error, std::abs(value - distance));
            if (cubic)
              gradient_error =
                std::max(gradient_error,
                         (level_set_gradient.at(node) - offset / r).norm());
          }
      }
    const std::string label =
      std::to_string(dim) + "D, " + (cubic ? "gradient augmented" : "linear") +
      (kept_cells > 0 ? ", kept " + std::to_string(kept_cells) + "h" : "") +
      ", ";
    unit_test::check_below(out,
                           label + "change of the nodes within " +
                             (kept_cells > 0
                                ? std::to_string(kept_cells) + "h - h/2"
                                : "h/4"),
                           Utilities::MPI::max(near_change, comm),
                           1e-15);
    out << label << "nodes beyond the kept ones: "
        << Utilities::MPI::sum(far_nodes, comm) << '\n';
    unit_test::check_below(
      out,
      label + "their error against r - R, over h",
      Utilities::MPI::max(distance_error, comm) / h,
      (t * t / (2 * far) + (cubic ? 0 : dim * h * h / (8 * R))) / h);
    if (cubic)
      unit_test::check_below(out,
                             label + "their gradient error, over h / R",
                             Utilities::MPI::max(gradient_error, comm) /
                               (h / R),
                             t / h);
    out << label << "nodes that changed sign: "
        << Utilities::MPI::sum(sign_changes, comm) << '\n';
  }
} // namespace

int
main(int argc, char **argv)
{
  return unit_test::run(argc, argv, [](std::ostream &out) {
    check<2>(out, vefs::LevelSetInterpolation::linear);
    check<2>(out, vefs::LevelSetInterpolation::gradient_augmented);
    check<2>(out, vefs::LevelSetInterpolation::gradient_augmented, 4);
    check<3>(out, vefs::LevelSetInterpolation::linear);
    check<3>(out, vefs::LevelSetInterpolation::gradient_augmented);
  });
}
