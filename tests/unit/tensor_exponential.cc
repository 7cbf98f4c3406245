// vefs::tensor_exponential() against matrices whose exponential is known in
// closed form: a diagonal one, a rotation generator (cos/sin) in 2D and 3D,
// a nilpotent one (the series ends), and a sum of commuting parts. Norms up
// to a few tens, as the velocity gradients of one step. Tolerance: relative
// error below 1e-13 (12 Taylor terms reach round-off at norm 1/2; each of
// the s squarings at most doubles the relative error, s <= 7 here).

#include "unit_test.h"

#include <vefs/stress/tensor_exponential.h>

#include <iostream>

using namespace dealii;

template <int dim>
double
relative_error(const Tensor<2, dim> &computed, const Tensor<2, dim> &exact)
{
  return (computed - exact).norm() / exact.norm();
}

int
main()
{
  std::ostream &out   = std::cout;
  const double  bound = 1e-13;

  // diag(a, b, c): diag(e^a, e^b, e^c), with a norm of 30.
  {
    for (const double scale : {0.1, 1., 10.})
      {
        Tensor<2, 3> A, exact;
        const double a[3] = {-2 * scale, 0.5 * scale, 2.5 * scale};
        for (unsigned int i = 0; i < 3; ++i)
          {
            A[i][i]     = a[i];
            exact[i][i] = std::exp(a[i]);
          }
        unit_test::check_below(out,
                               "diagonal, scale " + unit_test::text(scale),
                               relative_error(vefs::tensor_exponential(A),
                                              exact),
                               bound);
      }
  }

  // theta [[0, -1], [1, 0]]: the rotation by theta.
  for (const double theta : {0.3, 2., 25.})
    {
      Tensor<2, 2> A, exact;
      A[0][1]     = -theta;
      A[1][0]     = theta;
      exact[0][0] = exact[1][1] = std::cos(theta);
      exact[0][1]               = -std::sin(theta);
      exact[1][0]               = std::sin(theta);
      unit_test::check_below(out,
                             "rotation 2D, angle " + unit_test::text(theta),
                             relative_error(vefs::tensor_exponential(A), exact),
                             bound);
    }

  // The generator W of the rotation about the unit axis n by theta:
  // exp(W) = cos I + sin [n]x + (1 - cos) n n^T (Rodrigues).
  {
    const double theta = 7.;
    Tensor<1, 3> n({2., -1., 2.});
    Tensor<2, 3> cross, exact;
    n /= n.norm();
    cross[0][1] = -n[2];
    cross[0][2] = n[1];
    cross[1][0] = n[2];
    cross[1][2] = -n[0];
    cross[2][0] = -n[1];
    cross[2][1] = n[0];
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        exact[i][j] = (i == j ? std::cos(theta) : 0.) +
                      std::sin(theta) * cross[i][j] +
                      (1 - std::cos(theta)) * n[i] * n[j];
    unit_test::check_below(out,
                           "rotation 3D, angle 7",
                           relative_error(vefs::tensor_exponential(
                                            Tensor<2, 3>(theta * cross)),
                                          exact),
                           bound);
  }

  // Strictly upper triangular N (N^3 = 0): exp(N) = I + N + N^2 / 2, the
  // homogeneous shear of one step and more.
  for (const double scale : {0.2, 20.})
    {
      Tensor<2, 3> N;
      N[0][1] = 1.5 * scale;
      N[0][2] = -0.5 * scale;
      N[1][2] = 2 * scale;
      const Tensor<2, 3> exact =
        Tensor<2, 3>(unit_symmetric_tensor<3>()) + N + 0.5 * N * N;
      unit_test::check_below(out,
                             "nilpotent, scale " + unit_test::text(scale),
                             relative_error(vefs::tensor_exponential(N), exact),
                             bound);
    }

  // a I + theta W commute: e^a times the rotation.
  {
    const double a = -1.5, theta = 3.;
    Tensor<2, 2> A, exact;
    A[0][0] = A[1][1] = a;
    A[0][1]           = -theta;
    A[1][0]           = theta;
    exact[0][0] = exact[1][1] = std::exp(a) * std::cos(theta);
    exact[0][1]               = -std::exp(a) * std::sin(theta);
    exact[1][0]               = std::exp(a) * std::sin(theta);
    unit_test::check_below(out,
                           "dilation and rotation",
                           relative_error(vefs::tensor_exponential(A), exact),
                           bound);
  }

  // The zero tensor: exactly the identity.
  unit_test::check_zero(out,
                        "zero tensor, |exp(0) - I|",
                        (vefs::tensor_exponential(Tensor<2, 3>()) -
                         Tensor<2, 3>(unit_symmetric_tensor<3>()))
                          .norm());
}
