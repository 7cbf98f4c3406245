// make_initial_level_set() (initial_liquid.h): the signed distance to the
// initial free surface, against a brute-force one. The free surface of a
// box is made of its faces that do not lie on a cavity wall (a face on a
// wall wets it); the brute-force distance is the smallest distance to those
// faces, each a rectangle (segment in 2D) to which the point is projected
// by clamping, negative inside the box (whose wetted walls belong to the
// liquid). Checked at the points of a lattice of 21^dim points over the
// cavity, to round-off (1e-14 of the cavity):
// - 2D: the default water column, a box in the lower left corner (two
//   faces on walls), and a box away from the walls;
// - 3D: a box on the floor, and a box in a corner (three faces on walls);
// - a ball: |x - c| - R; a level set expression: the expression.

#include "unit_test.h"

#include <vefs/base/cavity.h>
#include <vefs/transport/initial_liquid.h>

#include <cmath>
#include <iostream>

using namespace dealii;

namespace
{
  template <int dim>
  Point<dim>
  point(const std::vector<double> &values)
  {
    Point<dim> p;
    for (unsigned int d = 0; d < dim; ++d)
      p[d] = values[d];
    return p;
  }

  /** The distance of @p p to the box's faces that are not on a wall. */
  template <int dim>
  double
  brute_force_distance(const Point<dim>             &p,
                       const Point<dim>             &lower,
                       const Point<dim>             &upper,
                       const vefs::CavityParameters &cavity)
  {
    const auto on_wall = [&](const unsigned int d, const unsigned int side) {
      return side == 0 ? std::abs(lower[d] - cavity.cavity_lower[d]) < 1e-12
                       : std::abs(upper[d] - cavity.cavity_upper[d]) < 1e-12;
    };
    // Inside: within the faces that are free (the wetted walls belong to
    // the liquid).
    bool inside = true;
    for (unsigned int d = 0; d < dim; ++d)
      inside = inside && (on_wall(d, 0) || p[d] > lower[d]) &&
               (on_wall(d, 1) || p[d] < upper[d]);
    double distance = std::numeric_limits<double>::max();
    for (unsigned int d = 0; d < dim; ++d)
      for (unsigned int side = 0; side < 2; ++side)
        {
          if (on_wall(d, side))
            continue;
          const double plane = side == 0 ? lower[d] : upper[d];
          Point<dim>   nearest;
          for (unsigned int e = 0; e < dim; ++e)
            nearest[e] = e == d ? plane : std::clamp(p[e], lower[e], upper[e]);
          distance = std::min(distance, p.distance(nearest));
        }
    return inside ? -distance : distance;
  }

  /** Largest difference of @p level_set and @p exact on the lattice. */
  template <int dim, typename Exact>
  double
  largest_difference(const Function<dim>          &level_set,
                     const Exact                  &exact,
                     const vefs::CavityParameters &cavity)
  {
    const unsigned int n      = 21;
    unsigned int       points = 1;
    for (unsigned int d = 0; d < dim; ++d)
      points *= n;
    double difference = 0;
    for (unsigned int i = 0; i < points; ++i)
      {
        Point<dim>   p;
        unsigned int rest = i;
        for (unsigned int d = 0; d < dim; ++d, rest /= n)
          p[d] = cavity.cavity_lower[d] +
                 (cavity.cavity_upper[d] - cavity.cavity_lower[d]) *
                   (rest % n) / (n - 1.);
        difference =
          std::max(difference, std::abs(level_set.value(p) - exact(p)));
      }
    return difference;
  }

  template <int dim>
  void
  check_box(std::ostream              &out,
            const std::string         &name,
            const std::vector<double> &cavity_upper,
            const std::vector<double> &box_lower,
            const std::vector<double> &box_upper)
  {
    vefs::CavityParameters cavity;
    cavity.cavity_lower.assign(dim, 0.);
    cavity.cavity_upper = cavity_upper;
    vefs::InitialLiquidParameters liquid;
    liquid.initial_shape   = "box";
    liquid.box_lower       = box_lower;
    liquid.box_upper       = box_upper;
    const auto level_set   = vefs::make_initial_level_set<dim>(liquid, cavity);
    const Point<dim> lower = point<dim>(box_lower),
                     upper = point<dim>(box_upper);
    unit_test::check_below(
      out,
      std::to_string(dim) + "D, box, " + name + ", difference",
      largest_difference<dim>(
        *level_set,
        [&](const Point<dim> &p) {
          return brute_force_distance(p, lower, upper, cavity);
        },
        cavity),
      1e-14);
  }
} // namespace

int
main(int argc, char **argv)
{
  return unit_test::run(argc, argv, [](std::ostream &out) {
    const vefs::InitialLiquidParameters defaults;
    const vefs::CavityParameters        default_cavity;
    check_box<2>(out,
                 "the default water column",
                 default_cavity.cavity_upper,
                 defaults.box_lower,
                 defaults.box_upper);
    check_box<2>(out, "away from the walls", {1, 0.5}, {0.2, 0.1}, {0.45, 0.3});
    check_box<3>(out,
                 "on the floor",
                 {1, 1, 0.5},
                 {0.2, 0.3, 0},
                 {0.6, 0.5, 0.2});
    check_box<3>(out, "in a corner", {1, 1, 0.5}, {0, 0, 0}, {0.3, 0.4, 0.25});

    vefs::CavityParameters cavity;
    cavity.cavity_lower = {0, 0};
    cavity.cavity_upper = {1, 0.5};
    vefs::InitialLiquidParameters liquid;
    liquid.initial_shape = "ball";
    liquid.ball_center   = {0.4, 0.2};
    liquid.ball_radius   = 0.15;
    const Point<2> center(0.4, 0.2);
    unit_test::check_below(out,
                           "2D, ball, difference",
                           largest_difference<2>(
                             *vefs::make_initial_level_set<2>(liquid, cavity),
                             [&](const Point<2> &p) {
                               return p.distance(center) - 0.15;
                             },
                             cavity),
                           1e-14);
    liquid.initial_shape        = "expression";
    liquid.level_set_expression = "y - 0.1 - 0.05*sin(2*pi*x)";
    unit_test::check_below(out,
                           "2D, expression, difference",
                           largest_difference<2>(
                             *vefs::make_initial_level_set<2>(liquid, cavity),
                             [](const Point<2> &p) {
                               return p[1] - 0.1 -
                                      0.05 * std::sin(2 * numbers::PI * p[0]);
                             },
                             cavity),
                           1e-14);
  });
}
