#include <deal.II/base/function_parser.h>
#include <deal.II/base/utilities.h>

#include <vefs/transport/initial_liquid.h>

namespace vefs
{
  namespace
  {
    /** Exact signed distance to the surface of an axis-aligned box. */
    template <int dim>
    class BoxDistance : public Function<dim>
    {
    public:
      BoxDistance(const Point<dim> &lower, const Point<dim> &upper)
        : lower(lower)
        , upper(upper)
      {
      }

      double
      value(const Point<dim> &p, const unsigned int = 0) const override
      {
        Tensor<1, dim> outside;
        double         largest_inside = -std::numeric_limits<double>::max();
        for (unsigned int d = 0; d < dim; ++d)
          {
            const double q = std::max(lower[d] - p[d], p[d] - upper[d]);
            outside[d]     = std::max(q, 0.);
            largest_inside = std::max(largest_inside, q);
          }
        return outside.norm() + std::min(largest_inside, 0.);
      }

    private:
      const Point<dim> lower, upper;
    };

    template <int dim>
    class BallDistance : public Function<dim>
    {
    public:
      BallDistance(const Point<dim> &center, const double radius)
        : center(center)
        , radius(radius)
      {
      }

      double
      value(const Point<dim> &p, const unsigned int = 0) const override
      {
        return p.distance(center) - radius;
      }

    private:
      const Point<dim> center;
      const double     radius;
    };

    template <int dim>
    std::unique_ptr<Function<dim>>
    parse_function(const std::string &expression,
                   const unsigned int n_components)
    {
      auto function = std::make_unique<FunctionParser<dim>>(n_components);
      function->initialize(dim == 2 ? "x,y,t" : "x,y,z,t",
                           Utilities::split_string_list(expression, ';'),
                           {{"pi", numbers::PI}},
                           true);
      return function;
    }
  } // namespace

  template <int dim>
  std::unique_ptr<Function<dim>>
  make_initial_level_set(const Parameters &parameters)
  {
    if (parameters.initial_shape == "box")
      {
        // A box face on (or beyond) a cavity wall is not a free surface:
        // move it out of the cavity so that the liquid wets that wall.
        Point<dim> lower = to_point<dim>(parameters.box_lower);
        Point<dim> upper = to_point<dim>(parameters.box_upper);
        for (unsigned int d = 0; d < dim; ++d)
          {
            const double size =
              parameters.cavity_upper[d] - parameters.cavity_lower[d];
            if (lower[d] <= parameters.cavity_lower[d] + 1e-12 * size)
              lower[d] = parameters.cavity_lower[d] - size;
            if (upper[d] >= parameters.cavity_upper[d] - 1e-12 * size)
              upper[d] = parameters.cavity_upper[d] + size;
          }
        return std::make_unique<BoxDistance<dim>>(lower, upper);
      }
    if (parameters.initial_shape == "ball")
      return std::make_unique<BallDistance<dim>>(to_point<dim>(
                                                   parameters.ball_center),
                                                 parameters.ball_radius);
    return parse_function<dim>(parameters.level_set_expression, 1);
  }

  template <int dim>
  std::unique_ptr<Function<dim>>
  make_initial_velocity(const Parameters &parameters)
  {
    return parse_function<dim>(parameters.initial_velocity, dim);
  }

  template <int dim>
  std::unique_ptr<Function<dim>>
  make_initial_stress(const Parameters &parameters)
  {
    if (parameters.initial_stress.empty())
      return nullptr;
    return parse_function<dim>(parameters.initial_stress, dim * (dim + 1) / 2);
  }

  template <int dim>
  std::unique_ptr<Function<dim>>
  make_prescribed_velocity(const Parameters &parameters)
  {
    return parse_function<dim>(parameters.prescribed_velocity, dim);
  }

  template <int dim>
  std::unique_ptr<Function<dim>>
  make_exact_final_level_set(const Parameters &parameters)
  {
    if (parameters.exact_final_level_set == "initial")
      return make_initial_level_set<dim>(parameters);
    return parse_function<dim>(parameters.exact_final_level_set, 1);
  }

  template <int dim>
  std::unique_ptr<Function<dim>>
  make_wall_velocity(const Parameters &parameters, const unsigned int wall)
  {
    return parse_function<dim>(parameters.wall_velocity[wall], dim);
  }

  template std::unique_ptr<Function<2>>
  make_initial_level_set<2>(const Parameters &);
  template std::unique_ptr<Function<3>>
  make_initial_level_set<3>(const Parameters &);
  template std::unique_ptr<Function<2>>
  make_initial_velocity<2>(const Parameters &);
  template std::unique_ptr<Function<3>>
  make_initial_velocity<3>(const Parameters &);
  template std::unique_ptr<Function<2>>
  make_initial_stress<2>(const Parameters &);
  template std::unique_ptr<Function<3>>
  make_initial_stress<3>(const Parameters &);
  template std::unique_ptr<Function<2>>
  make_prescribed_velocity<2>(const Parameters &);
  template std::unique_ptr<Function<3>>
  make_prescribed_velocity<3>(const Parameters &);
  template std::unique_ptr<Function<2>>
  make_exact_final_level_set<2>(const Parameters &);
  template std::unique_ptr<Function<3>>
  make_exact_final_level_set<3>(const Parameters &);
  template std::unique_ptr<Function<2>>
  make_wall_velocity<2>(const Parameters &, const unsigned int);
  template std::unique_ptr<Function<3>>
  make_wall_velocity<3>(const Parameters &, const unsigned int);
} // namespace vefs
