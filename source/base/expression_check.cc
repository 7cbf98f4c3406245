#include <deal.II/base/function_parser.h>
#include <deal.II/base/utilities.h>
#include <deal.II/lac/vector.h>

#include <vefs/base/errors.h>
#include <vefs/base/expression_check.h>

#include <iostream>
#include <sstream>

namespace vefs
{
  using namespace dealii;

  namespace
  {
    std::string
    variable_names(const unsigned int dim)
    {
      return dim == 2 ? "x,y,t" : "x,y,z,t";
    }

    /** Grid points per direction: fine enough to find a pole planted at a
     * simple coordinate (the center, a wall, a tenth), cheap in 3D. */
    constexpr unsigned int points_per_direction = 11;
  } // namespace

  template <int dim>
  void
  check_expression(const std::string        &expression,
                   const unsigned int        n_components,
                   const std::string        &entry,
                   const ExpressionSampling &sampling)
  {
    const auto parts = Utilities::split_string_list(expression, ';');
    if (parts.size() != n_components)
      throw InputError(
        "entry '" + entry + "': needs " + std::to_string(n_components) +
        " expression(s) separated by ';', got '" + expression + "'");
    // muParser reports its own diagnosis on the standard streams; the
    // user gets ours, naming the entry, instead.
    std::ostringstream silenced;
    auto *const        out_buffer = std::cout.rdbuf(silenced.rdbuf());
    auto *const        err_buffer = std::cerr.rdbuf(silenced.rdbuf());
    bool               valid      = true;
    std::string        failure;
    try
      {
        FunctionParser<dim> function(n_components);
        function.initialize(variable_names(dim),
                            parts,
                            {{"pi", numbers::PI}},
                            true);
        Vector<double>     value(n_components);
        const unsigned int n        = points_per_direction - 1;
        unsigned int       n_points = 1;
        for (unsigned int d = 0; d < dim; ++d)
          n_points *= points_per_direction;
        for (const double t : sampling.times)
          {
            function.set_time(t);
            for (unsigned int i = 0; i < n_points && failure.empty(); ++i)
              {
                Point<dim>   p;
                unsigned int index = i;
                for (unsigned int d = 0; d < dim; ++d)
                  {
                    const unsigned int k = index % points_per_direction;
                    index /= points_per_direction;
                    p[d] = sampling.lower[d] +
                           (sampling.upper[d] - sampling.lower[d]) * k / n;
                  }
                function.vector_value(p, value);
                for (unsigned int c = 0; c < n_components; ++c)
                  if (!std::isfinite(value[c]))
                    {
                      std::ostringstream where;
                      where << "component " << c + 1 << " ('" << parts[c]
                            << "') is "
                            << (std::isnan(value[c]) ? "NaN"
                                : value[c] > 0       ? "inf"
                                                     : "-inf")
                            << " at";
                      for (unsigned int d = 0; d < dim; ++d)
                        where << (d == 0 ? " " : ", ") << "xyz"[d] << " = "
                              << p[d];
                      where << ", t = " << t;
                      failure = where.str();
                      break;
                    }
              }
            if (!failure.empty())
              break;
          }
      }
    catch (...)
      {
        valid = false;
      }
    std::cout.rdbuf(out_buffer);
    std::cerr.rdbuf(err_buffer);
    if (!valid)
      throw InputError("entry '" + entry + "': '" + expression +
                       "' is not a valid muParser expression in the "
                       "variables " +
                       variable_names(dim));
    if (!failure.empty())
      throw InputError("entry '" + entry +
                       "': the expression is not finite: " + failure +
                       "; it must be finite everywhere in the cavity at "
                       "every time of the run");
  }

  template void
  check_expression<2>(const std::string &,
                      const unsigned int,
                      const std::string &,
                      const ExpressionSampling &);
  template void
  check_expression<3>(const std::string &,
                      const unsigned int,
                      const std::string &,
                      const ExpressionSampling &);
} // namespace vefs
