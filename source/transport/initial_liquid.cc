#include <deal.II/base/function_parser.h>
#include <deal.II/base/utilities.h>

#include <vefs/base/parameter_entries.h>
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
  make_initial_level_set(const InitialLiquidParameters &parameters,
                         const CavityParameters        &cavity)
  {
    if (parameters.initial_shape == "box")
      {
        // A box face on (or beyond) a cavity wall is not a free surface:
        // move it out of the cavity so that the liquid wets that wall.
        Point<dim> lower = to_point<dim>(parameters.box_lower);
        Point<dim> upper = to_point<dim>(parameters.box_upper);
        for (unsigned int d = 0; d < dim; ++d)
          {
            const double size = cavity.cavity_upper[d] - cavity.cavity_lower[d];
            if (lower[d] <= cavity.cavity_lower[d] + 1e-12 * size)
              lower[d] = cavity.cavity_lower[d] - size;
            if (upper[d] >= cavity.cavity_upper[d] - 1e-12 * size)
              upper[d] = cavity.cavity_upper[d] + size;
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
  make_initial_velocity(const InitialLiquidParameters &parameters)
  {
    return parse_function<dim>(parameters.initial_velocity, dim);
  }

  template <int dim>
  std::unique_ptr<Function<dim>>
  make_initial_stress(const InitialLiquidParameters &parameters)
  {
    if (parameters.initial_stress.empty())
      return nullptr;
    return parse_function<dim>(parameters.initial_stress, dim * (dim + 1) / 2);
  }

  template <int dim>
  std::unique_ptr<Function<dim>>
  make_prescribed_velocity(const std::string &expression)
  {
    return parse_function<dim>(expression, dim);
  }

  template <int dim>
  std::unique_ptr<Function<dim>>
  make_exact_final_level_set(const std::string             &expression,
                             const InitialLiquidParameters &initial,
                             const CavityParameters        &cavity)
  {
    if (expression == "initial")
      return make_initial_level_set<dim>(initial, cavity);
    return parse_function<dim>(expression, 1);
  }

  template <int dim>
  std::unique_ptr<Function<dim>>
  make_wall_velocity(const CavityParameters &cavity, const unsigned int wall)
  {
    return parse_function<dim>(cavity.wall_velocity[wall], dim);
  }

  void
  InitialLiquidParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Initial liquid");
    {
      prm.add_parameter("Shape",
                        initial_shape,
                        "Shape of the liquid at t = 0: a box, a ball, or "
                        "the region where 'Level set expression' < 0.",
                        Patterns::Selection("box|ball|expression"));
      prm.add_parameter(
        "Box lower corner",
        box_lower,
        "Lower corner of the liquid box (m). A box face on a cavity wall "
        "wets that wall (it is not a free surface).",
        Patterns::List(Patterns::Double(), 2, 3));
      prm.add_parameter("Box upper corner",
                        box_upper,
                        "Upper corner of the liquid box (m).",
                        Patterns::List(Patterns::Double(), 2, 3));
      prm.add_parameter("Ball center",
                        ball_center,
                        "Center of the liquid ball (m).",
                        Patterns::List(Patterns::Double(), 2, 3));
      prm.add_parameter("Ball radius",
                        ball_radius,
                        "Radius of the liquid ball (m).",
                        Patterns::Double(0));
      prm.add_parameter("Level set expression",
                        level_set_expression,
                        "muParser expression in x, y, (z): the liquid is "
                        "where it is negative. It should be close to a "
                        "signed distance (m) near its zero level.",
                        Patterns::Anything());
      prm.add_parameter("Velocity",
                        initial_velocity,
                        "Initial velocity (m/s): one muParser expression "
                        "per component, separated by ';', in x, y, (z). All "
                        "expressions know the constant pi.",
                        Patterns::Anything());
      prm.add_parameter("Stress",
                        initial_stress,
                        "Initial extra stress sigma (Pa) in the Oldroyd-B and "
                        "elastic regimes: muParser expressions in x, y, (z) "
                        "for the components xx; yy; xy (2D) or xx; yy; zz; "
                        "xy; xz; yz (3D). Empty: zero.",
                        Patterns::Anything());
    }
    prm.leave_subsection();
  }

  void
  InitialLiquidParameters::check(const unsigned int        dimension,
                                 const CavityParameters   &cavity,
                                 std::vector<std::string> &warnings) const
  {
    const auto &cavity_lower = cavity.cavity_lower;
    const auto &cavity_upper = cavity.cavity_upper;
    if (initial_shape == "box")
      {
        require_point(box_lower, dimension, "Initial liquid/Box lower corner");
        require_point(box_upper, dimension, "Initial liquid/Box upper corner");
        for (unsigned int d = 0; d < dimension; ++d)
          require(box_lower[d] < box_upper[d],
                  "Initial liquid/Box upper corner",
                  "must exceed 'Box lower corner' in every coordinate");
        for (unsigned int d = 0; d < dimension; ++d)
          require(box_lower[d] < cavity_upper[d] &&
                    box_upper[d] > cavity_lower[d],
                  "Initial liquid/Box upper corner",
                  "the liquid box lies outside the cavity");
        for (unsigned int d = 0; d < dimension; ++d)
          if (box_lower[d] < cavity_lower[d] || box_upper[d] > cavity_upper[d])
            {
              warnings.push_back(
                entry_message("Initial liquid/Box upper corner",
                              "the liquid box reaches beyond the cavity; only "
                              "its part inside the cavity is liquid"));
              break;
            }
      }
    else if (initial_shape == "ball")
      {
        require_point(ball_center, dimension, "Initial liquid/Ball center");
        require(ball_radius > 0,
                "Initial liquid/Ball radius",
                "must be positive");
        for (unsigned int d = 0; d < dimension; ++d)
          if (ball_center[d] - ball_radius < cavity_lower[d] ||
              ball_center[d] + ball_radius > cavity_upper[d])
            {
              warnings.push_back(
                entry_message("Initial liquid/Ball radius",
                              "the liquid ball reaches beyond the cavity; only "
                              "its part inside the cavity is liquid"));
              break;
            }
      }
  }

  template std::unique_ptr<Function<2>>
  make_initial_level_set<2>(const InitialLiquidParameters &,
                            const CavityParameters &);
  template std::unique_ptr<Function<3>>
  make_initial_level_set<3>(const InitialLiquidParameters &,
                            const CavityParameters &);
  template std::unique_ptr<Function<2>>
  make_initial_velocity<2>(const InitialLiquidParameters &);
  template std::unique_ptr<Function<3>>
  make_initial_velocity<3>(const InitialLiquidParameters &);
  template std::unique_ptr<Function<2>>
  make_initial_stress<2>(const InitialLiquidParameters &);
  template std::unique_ptr<Function<3>>
  make_initial_stress<3>(const InitialLiquidParameters &);
  template std::unique_ptr<Function<2>>
  make_prescribed_velocity<2>(const std::string &);
  template std::unique_ptr<Function<3>>
  make_prescribed_velocity<3>(const std::string &);
  template std::unique_ptr<Function<2>>
  make_exact_final_level_set<2>(const std::string &,
                                const InitialLiquidParameters &,
                                const CavityParameters &);
  template std::unique_ptr<Function<3>>
  make_exact_final_level_set<3>(const std::string &,
                                const InitialLiquidParameters &,
                                const CavityParameters &);
  template std::unique_ptr<Function<2>>
  make_wall_velocity<2>(const CavityParameters &, const unsigned int);
  template std::unique_ptr<Function<3>>
  make_wall_velocity<3>(const CavityParameters &, const unsigned int);
} // namespace vefs
