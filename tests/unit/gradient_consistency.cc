// hold_gradient_to_values() (gradient_consistency.h), 1 and 2 ranks, on a
// uniform mesh with psi = a . x + b, whose Q1 values have the exact
// gradient a at every node (the boundary nodes' one-sided differences
// included):
// - the carried gradient a itself: no node changed;
// - the carried gradient a + e with |e| = 1.5 max(1, |a|) (beyond the bound
//   1) at the nodes with x < 0.3, and |e| = 0.5 max(1, |a|) (within it)
//   elsewhere: exactly the nodes with x < 0.3 change, counted by the test
//   over all ranks, and they hold a (tolerance 1e-12, a being O(1)); the
//   others keep a + e.
// - the same with a scaled by 4 (|a| = 2.4, a steep level set): the bound
//   scales with |a|.

#include "unit_test.h"

#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/grid/grid_generator.h>

#include <vefs/transport/gradient_consistency.h>

#include <iostream>

using namespace dealii;

namespace
{
  template <int dim>
  void
  check(std::ostream &out, const double steepness)
  {
    const MPI_Comm                            comm = MPI_COMM_WORLD;
    parallel::distributed::Triangulation<dim> triangulation(comm);
    GridGenerator::hyper_cube(triangulation);
    triangulation.refine_global(dim == 2 ? 4 : 3);
    vefs::TransportedFields<dim> fields(triangulation, false, false, {});
    fields.setup_dofs();

    Tensor<1, dim> a, e;
    for (unsigned int d = 0; d < dim; ++d)
      {
        a[d] = steepness * (0.6 - 0.5 * d);
        e[d] = 1. + 0.3 * d;
      }
    const double scale = std::max(1., a.norm());
    e *= scale / e.norm();
    for (const auto &node : fields.nodes())
      fields.set_level_set(node, a * node.point + 0.2);
    fields.finalize();

    vefs::LevelSetGradient<dim> gradient;
    gradient.reinit(fields);
    for (const auto &node : fields.nodes())
      gradient.set(node, a);
    gradient.finalize(fields);
    const std::string label = std::to_string(dim) + "D, a scaled by " +
                              unit_test::text(steepness) + ", ";
    out << label << "carried gradient a: nodes changed: "
        << vefs::hold_gradient_to_values(fields, gradient, 1.) << '\n';

    types::global_dof_index turned = 0;
    for (const auto &node : fields.nodes())
      {
        const bool beyond = node.point[0] < 0.3;
        gradient.set(node, a + (beyond ? 1.5 : 0.5) * e);
        turned += beyond;
      }
    gradient.finalize(fields);
    const auto changed = vefs::hold_gradient_to_values(fields, gradient, 1.);
    double     error   = 0;
    for (const auto &node : fields.nodes())
      error = std::max(
        error,
        (gradient.at(node) - (node.point[0] < 0.3 ? a : a + 0.5 * e)).norm());
    out << label << "a + 1.5 e where x < 0.3, a + 0.5 e elsewhere: nodes "
        << "changed = nodes with x < 0.3: "
        << (changed == Utilities::MPI::sum(turned, comm) && changed > 0 ? "yes"
                                                                        : "NO")
        << '\n';
    unit_test::check_below(out,
                           label + "gradient error (a there, a + 0.5 e "
                                   "elsewhere)",
                           Utilities::MPI::max(error, comm),
                           1e-12);
  }
} // namespace

int
main(int argc, char **argv)
{
  return unit_test::run(argc, argv, [](std::ostream &out) {
    check<2>(out, 1.);
    check<3>(out, 1.);
    check<2>(out, 4.);
  });
}
