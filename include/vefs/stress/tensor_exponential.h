#ifndef vefs_tensor_exponential_h
#define vefs_tensor_exponential_h

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <cmath>

namespace vefs
{
  using namespace dealii;

  /**
   * exp(A) of a (not necessarily symmetric) small tensor by scaling and
   * squaring: A / 2^s has a norm below 1/2, where 12 Taylor terms reach
   * round-off; the result is then squared s times. Used for the velocity
   * gradient of one time step, whose norm is at most a few tens.
   */
  template <int dim>
  Tensor<2, dim>
  tensor_exponential(const Tensor<2, dim> &A)
  {
    const double norm    = A.norm();
    const int    squares = norm > 0.5 ? int(std::ceil(std::log2(2 * norm))) : 0;
    const Tensor<2, dim> scaled = A / std::ldexp(1., squares);

    Tensor<2, dim> result = unit_symmetric_tensor<dim>();
    Tensor<2, dim> term   = unit_symmetric_tensor<dim>();
    for (unsigned int k = 1; k <= 12; ++k)
      {
        term = term * scaled / double(k);
        result += term;
      }
    for (int i = 0; i < squares; ++i)
      result = result * result;
    return result;
  }
} // namespace vefs

#endif
