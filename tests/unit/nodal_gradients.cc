// recover_nodal_gradients() (nodal_gradients.h): the mean over the cells
// around a node of the cells' Q1 gradients is, on a uniform mesh, a central
// difference. Checked at the nodes away from the boundary (there every node
// has all its cells around), 1 and 2 ranks, the dim velocity components:
// - exact for polynomials of total degree 2 (the central difference of a
//   quadratic is its derivative; the mean over the rows above and below of
//   a term linear in the other direction is its value on the node's row):
//   tolerance 1e-12, the polynomials being O(1) on the unit cube;
// - second order for a smooth field (sines): the largest error falls by
//   at least 3.5 (against 4) from h = 1/16 to 1/32 (2D) and from 1/8 to
//   1/16 (3D).

#include "unit_test.h"

#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/grid/grid_generator.h>

#include <vefs/transport/nodal_gradients.h>

#include <functional>
#include <iostream>

using namespace dealii;

namespace
{
  /** A field per component c and its gradient. */
  template <int dim>
  struct Field
  {
    std::function<double(const Point<dim> &, unsigned int)>         value;
    std::function<Tensor<1, dim>(const Point<dim> &, unsigned int)> gradient;
  };

  /** Total degree 2, all monomials present, different per component. */
  template <int dim>
  Field<dim>
  quadratic()
  {
    // f = 0.2 + sum_d a_d x_d + sum_{d <= e} b_de x_d x_e, coefficients
    // shifted by the component.
    const auto a = [](unsigned int d, unsigned int c) {
      return 0.7 - 0.4 * d + 0.3 * c;
    };
    const auto b = [](unsigned int d, unsigned int e, unsigned int c) {
      return 1.1 - 0.5 * d + 0.3 * e - 0.7 * c;
    };
    return {[=](const Point<dim> &p, unsigned int c) {
              double f = 0.2;
              for (unsigned int d = 0; d < dim; ++d)
                {
                  f += a(d, c) * p[d];
                  for (unsigned int e = d; e < dim; ++e)
                    f += b(d, e, c) * p[d] * p[e];
                }
              return f;
            },
            [=](const Point<dim> &p, unsigned int c) {
              Tensor<1, dim> g;
              for (unsigned int d = 0; d < dim; ++d)
                {
                  g[d] += a(d, c);
                  for (unsigned int e = d; e < dim; ++e)
                    {
                      g[d] += b(d, e, c) * p[e];
                      g[e] += b(d, e, c) * p[d];
                    }
                }
              return g;
            }};
  }

  /** prod_d sin(k_d x_d + c), not reproduced by any difference. */
  template <int dim>
  Field<dim>
  smooth()
  {
    const auto k = [](unsigned int d) { return 2.1 + 0.7 * d; };
    return {[=](const Point<dim> &p, unsigned int c) {
              double f = 1;
              for (unsigned int d = 0; d < dim; ++d)
                f *= std::sin(k(d) * p[d] + c);
              return f;
            },
            [=](const Point<dim> &p, unsigned int c) {
              Tensor<1, dim> g;
              for (unsigned int d = 0; d < dim; ++d)
                {
                  g[d] = k(d) * std::cos(k(d) * p[d] + c);
                  for (unsigned int e = 0; e < dim; ++e)
                    if (e != d)
                      g[d] *= std::sin(k(e) * p[e] + c);
                }
              return g;
            }};
  }

  /** The largest gradient error at the interior nodes, level @p level. */
  template <int dim>
  double
  largest_error(const Field<dim> &field, const unsigned int level)
  {
    const MPI_Comm                            comm = MPI_COMM_WORLD;
    parallel::distributed::Triangulation<dim> triangulation(comm);
    GridGenerator::hyper_cube(triangulation, 0, 1);
    triangulation.refine_global(level);
    const double h = 1. / (1u << level);

    // Velocity components: the first dim fields.
    vefs::TransportedFields<dim> fields(triangulation, false, false, {});
    fields.setup_dofs();
    for (const auto &node : fields.nodes())
      for (unsigned int c = 0; c < dim; ++c)
        fields.set_value(node, c, field.value(node.point, c));
    fields.finalize();

    const auto gradients = vefs::recover_nodal_gradients(fields, dim);
    double     error     = 0;
    for (const auto &node : fields.nodes())
      {
        bool interior = true;
        for (unsigned int d = 0; d < dim; ++d)
          interior =
            interior && node.point[d] > h / 2 && node.point[d] < 1 - h / 2;
        if (interior)
          for (unsigned int c = 0; c < dim; ++c)
            {
              const Tensor<1, dim> exact = field.gradient(node.point, c);
              for (unsigned int j = 0; j < dim; ++j)
                error =
                  std::max(error,
                           std::abs(gradients[j](node.dofs[c]) - exact[j]));
            }
      }
    return Utilities::MPI::max(error, comm);
  }

  template <int dim>
  void
  check(std::ostream &out, const unsigned int level)
  {
    const std::string label = std::to_string(dim) + "D, ";
    unit_test::check_below(out,
                           label + "quadratic, gradient error",
                           largest_error(quadratic<dim>(), level),
                           1e-12);
    const double coarse = largest_error(smooth<dim>(), level);
    const double fine   = largest_error(smooth<dim>(), level + 1);
    if (std::getenv("VEFS_UNIT_VERBOSE"))
      std::cerr << label << "smooth field, error ratio: " << coarse / fine
                << '\n';
    out << label << "smooth field, error ratio from h to h/2 at least 3.5: "
        << (fine * 3.5 <= coarse
              ? "yes"
              : "NO (" + unit_test::text(coarse / fine) + ")")
        << '\n';
  }
} // namespace

int
main(int argc, char **argv)
{
  return unit_test::run(argc, argv, [](std::ostream &out) {
    check<2>(out, 4);
    check<3>(out, 3);
  });
}
