#ifndef vefs_expression_check_h
#define vefs_expression_check_h

#include <string>
#include <vector>

namespace vefs
{
  /**
   * Where and when a muParser expression is evaluated by the run: a box
   * (lower[d] == upper[d] for a wall) and a list of times.
   */
  struct ExpressionSampling
  {
    std::vector<double> lower;
    std::vector<double> upper;
    std::vector<double> times;
  };

  /**
   * Parse the @p n_components expressions of @p expression (separated by
   * ';', in x, y, (z,) t) and evaluate them on a grid of points of
   * @p sampling at each of its times, so that a typo or a value that is
   * not finite (a pole, a NaN) stops the run before any work. Throws
   * InputError naming @p entry and, for a non-finite value, the point.
   */
  template <int dim>
  void
  check_expression(const std::string        &expression,
                   const unsigned int        n_components,
                   const std::string        &entry,
                   const ExpressionSampling &sampling);
} // namespace vefs

#endif
