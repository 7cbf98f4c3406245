#include <vefs/transport/midpoint_fallback.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace vefs
{
  template <int dim>
  std::optional<BoundingBox<dim>>
  midpoint_fallback_box(const Point<dim>  &point,
                        const double       weight,
                        const unsigned int max_box_splits)
  {
    // A box split k times in halves has sides 2^-a_d; its centre lies at
    // odd multiples of 2^-(a_d + 1), exact in floating point.
    const double finest = std::ldexp(1., static_cast<int>(max_box_splits) + 1);
    Point<dim>   lower, upper;
    double       volume = 1;
    for (unsigned int d = 0; d < dim; ++d)
      {
        const double scaled = point[d] * finest;
        if (!(scaled > 0 && scaled < finest) || scaled != std::floor(scaled))
          return std::nullopt;
        long multiple = static_cast<long>(scaled);
        int  halvings = static_cast<int>(max_box_splits) + 1;
        while (multiple % 2 == 0)
          {
            multiple /= 2;
            --halvings;
          }
        const double side = std::ldexp(1., 1 - halvings);
        if (side > 1)
          return std::nullopt;
        lower[d] = point[d] - side / 2;
        upper[d] = point[d] + side / 2;
        volume *= side;
      }
    if (volume != weight)
      return std::nullopt;
    return BoundingBox<dim>(std::make_pair(lower, upper));
  }

  template <int dim>
  double
  corner_liquid_fraction(const Function<dim>    &level_set,
                         const BoundingBox<dim> &box,
                         double                 &derivative)
  {
    double lowest  = std::numeric_limits<double>::max();
    double highest = -lowest;
    for (unsigned int v = 0; v < (1u << dim); ++v)
      {
        Point<dim> corner;
        for (unsigned int d = 0; d < dim; ++d)
          corner[d] = ((v >> d) & 1) ? box.get_boundary_points().second[d]
                                     : box.get_boundary_points().first[d];
        const double value = level_set.value(corner);
        lowest             = std::min(lowest, value);
        highest            = std::max(highest, value);
      }
    derivative = 0;
    if (!(lowest < 0))
      return 0;
    if (highest <= 0)
      return 1;
    derivative = -1 / (highest - lowest);
    return -lowest / (highest - lowest);
  }

  template <int dim>
  void
  append_corner_quadrature(const Function<dim>     &level_set,
                           const BoundingBox<dim>  &box,
                           const unsigned int       n,
                           std::vector<Point<dim>> &points,
                           std::vector<double>     &weights,
                           double                  &derivative)
  {
    const Point<dim> &lower      = box.get_boundary_points().first;
    const Point<dim> &upper      = box.get_boundary_points().second;
    const double      sub_volume = box.volume() / std::pow(n, dim);
    unsigned int      n_sub      = 1;
    for (unsigned int d = 0; d < dim; ++d)
      n_sub *= n;
    for (unsigned int s = 0; s < n_sub; ++s)
      {
        Point<dim>   sub_lower, sub_upper;
        unsigned int index = s;
        for (unsigned int d = 0; d < dim; ++d, index /= n)
          {
            const double side = (upper[d] - lower[d]) / n;
            sub_lower[d]      = lower[d] + (index % n) * side;
            sub_upper[d]      = sub_lower[d] + side;
          }
        const BoundingBox<dim> sub_box(std::make_pair(sub_lower, sub_upper));
        double                 slope = 0;
        const double           fraction =
          corner_liquid_fraction(level_set, sub_box, slope);
        derivative += slope * sub_volume;
        if (fraction > 0)
          {
            points.push_back(sub_box.center());
            weights.push_back(fraction * sub_volume);
          }
      }
  }

  template std::optional<BoundingBox<2>>
  midpoint_fallback_box(const Point<2> &, const double, const unsigned int);
  template std::optional<BoundingBox<3>>
  midpoint_fallback_box(const Point<3> &, const double, const unsigned int);
  template double
  corner_liquid_fraction(const Function<2> &, const BoundingBox<2> &, double &);
  template double
  corner_liquid_fraction(const Function<3> &, const BoundingBox<3> &, double &);
  template void
  append_corner_quadrature(const Function<2> &,
                           const BoundingBox<2> &,
                           const unsigned int,
                           std::vector<Point<2>> &,
                           std::vector<double> &,
                           double &);
  template void
  append_corner_quadrature(const Function<3> &,
                           const BoundingBox<3> &,
                           const unsigned int,
                           std::vector<Point<3>> &,
                           std::vector<double> &,
                           double &);
} // namespace vefs
