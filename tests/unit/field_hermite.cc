// FieldHermite (field_hermite.h): the tensor-product cubic Hermite
// interpolant reproduces a polynomial of degree <= 3 in each variable if
// its nodal derivatives are exact. Checked in the cells away from the
// boundary of a uniform mesh (there every node has all its cells around,
// and the mean of the cells' one-sided differences is a central
// difference), 1 and 2 ranks:
// - gradient augmented: the level set gradient given exactly, the mixed
//   derivatives recovered from it by central differences, exact for a
//   polynomial of total degree 3 (its gradient is quadratic): value and
//   gradient of the interpolant equal f and grad f.
// - recovered from the values alone: the central differences are exact
//   for a polynomial of degree <= 2 in each variable.
// Tolerance: 1e-12 (the polynomials and their derivatives are O(1), h =
// 1/8).

#include "unit_test.h"

#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/grid/grid_generator.h>

#include <vefs/transport/field_hermite.h>

#include <functional>
#include <iostream>

using namespace dealii;

namespace
{
  template <int dim>
  struct Polynomial
  {
    std::function<double(const Point<dim> &)>         value;
    std::function<Tensor<1, dim>(const Point<dim> &)> gradient;
  };

  /** Total degree 3, all monomials present (z only in 3D). */
  template <int dim>
  Polynomial<dim>
  cubic()
  {
    return {[](const Point<dim> &p) {
              const double x = p[0], y = p[1], z = dim == 3 ? p[2] : 0.;
              return 0.3 - x + 0.5 * y + x * x * x - 2 * x * x * y +
                     0.7 * x * y * y - 1.3 * y * y * y + 0.4 * x * y +
                     z * (1.1 * x * y - 0.6 * z * z + 0.9 * x * z - y + 0.2);
            },
            [](const Point<dim> &p) {
              const double   x = p[0], y = p[1], z = dim == 3 ? p[2] : 0.;
              Tensor<1, dim> g;
              g[0] = -1 + 3 * x * x - 4 * x * y + 0.7 * y * y + 0.4 * y +
                     z * (1.1 * y + 0.9 * z);
              g[1] = 0.5 - 2 * x * x + 1.4 * x * y - 3.9 * y * y + 0.4 * x +
                     z * (1.1 * x - 1);
              if (dim == 3)
                g[dim - 1] = 1.1 * x * y - 1.8 * z * z + 1.8 * x * z - y + 0.2;
              return g;
            }};
  }

  /** Degree 2 in each variable: (x^2 - x + 0.5)(y^2 + 0.3 y - 1)(...z). */
  template <int dim>
  Polynomial<dim>
  quadratic_in_each()
  {
    const auto factors = [](const Point<dim> &p) {
      std::array<double, 3> f{{1, 1, 1}}, df{{0, 0, 0}};
      const double          a[3] = {-1, 0.3, 0.8}, b[3] = {0.5, -1, 0.1};
      for (unsigned int d = 0; d < dim; ++d)
        {
          f[d]  = p[d] * p[d] + a[d] * p[d] + b[d];
          df[d] = 2 * p[d] + a[d];
        }
      return std::make_pair(f, df);
    };
    return {[=](const Point<dim> &p) {
              const auto [f, df] = factors(p);
              return f[0] * f[1] * f[2];
            },
            [=](const Point<dim> &p) {
              const auto [f, df] = factors(p);
              Tensor<1, dim> g;
              for (unsigned int d = 0; d < dim; ++d)
                {
                  g[d] = df[d];
                  for (unsigned int e = 0; e < dim; ++e)
                    if (e != d)
                      g[d] *= f[e];
                }
              return g;
            }};
  }

  template <int dim>
  void
  check(std::ostream          &out,
        const std::string     &name,
        const Polynomial<dim> &f,
        const bool             advected_gradient)
  {
    const MPI_Comm                            comm = MPI_COMM_WORLD;
    parallel::distributed::Triangulation<dim> triangulation(comm);
    GridGenerator::hyper_cube(triangulation, -0.5, 1.5);
    triangulation.refine_global(dim == 2 ? 4 : 3);
    vefs::TransportedFields<dim> fields(triangulation, false, false, {});
    fields.setup_dofs();
    vefs::LevelSetGradient<dim> level_set_gradient;
    level_set_gradient.reinit(fields);
    for (const auto &node : fields.nodes())
      {
        fields.set_level_set(node, f.value(node.point));
        level_set_gradient.set(node, f.gradient(node.point));
      }
    fields.finalize();
    level_set_gradient.finalize(fields);

    vefs::FieldHermite<dim> hermite;
    hermite.recover(fields, advected_gradient ? &level_set_gradient : nullptr);
    double value_error = 0, gradient_error = 0;
    // Points inside the cells and on their faces and vertices.
    const double xis[4] = {0, 0.21, 0.5, 0.87};
    for (const auto &cell : fields.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && !cell->at_boundary())
        for (unsigned int k = 0; k < (1u << (2 * dim)); ++k)
          {
            Point<dim> xi;
            for (unsigned int d = 0; d < dim; ++d)
              xi[d] = xis[(k >> (2 * d)) & 3];
            Point<dim> p = cell->vertex(0);
            for (unsigned int d = 0; d < dim; ++d)
              p[d] += xi[d] * (cell->vertex(1u << d)[d] - cell->vertex(0)[d]);
            Tensor<1, dim> gradient;
            const double   value = hermite.value(fields,
                                               cell,
                                               fields.vertex_entries(cell),
                                               xi,
                                               false,
                                               &gradient);
            value_error = std::max(value_error, std::abs(value - f.value(p)));
            gradient_error =
              std::max(gradient_error, (gradient - f.gradient(p)).norm());
          }
    const std::string label = std::to_string(dim) + "D, " + name + ", ";
    unit_test::check_below(out,
                           label + "value error",
                           Utilities::MPI::max(value_error, comm),
                           1e-12);
    unit_test::check_below(out,
                           label + "gradient error",
                           Utilities::MPI::max(gradient_error, comm),
                           1e-12);
  }
} // namespace

int
main(int argc, char **argv)
{
  return unit_test::run(argc, argv, [](std::ostream &out) {
    check<2>(out, "cubic, gradient augmented", cubic<2>(), true);
    check<3>(out, "cubic, gradient augmented", cubic<3>(), true);
    check<2>(out,
             "quadratic in each, recovered",
             quadratic_in_each<2>(),
             false);
    check<3>(out,
             "quadratic in each, recovered",
             quadratic_in_each<3>(),
             false);
  });
}
