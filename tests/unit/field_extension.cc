// extend_flow_fields() (field_extension.h) on a uniform mesh of the unit
// square (cube), h = 1/16, with the liquid's nodes x <= 1/2 known and three
// layers of extension, 1 and 2 ranks. Each layer gives an unknown node the
// mean over its cells at the front of their known nodes' averages; at a
// planar front that is (f(y - h) + 2 f(y) + f(y + h)) / 4 in each
// tangential direction, so exact answers are:
// - a constant (velocity and stress alike) is extended exactly (1e-14);
// - a field linear along the front, a + b y (+ c z), is extended exactly
//   (1e-13) at the nodes at least three cells from the cavity's walls
//   across the front (a wall node has one cell on one side only, and its
//   error moves inward one node per layer);
// - the nodes of the three layers, and no others, are flagged known; the
//   nodes beyond hold zero.

#include "unit_test.h"

#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/grid/grid_generator.h>

#include <vefs/transport/field_extension.h>

#include <cmath>
#include <iostream>

using namespace dealii;

namespace
{
  template <int dim>
  void
  check(std::ostream &out)
  {
    const MPI_Comm                            comm = MPI_COMM_WORLD;
    parallel::distributed::Triangulation<dim> triangulation(comm);
    GridGenerator::hyper_cube(triangulation, 0, 1);
    const unsigned int level = 4;
    triangulation.refine_global(level);
    const double       h        = 1. / (1u << level);
    const double       front    = 0.5;
    const unsigned int n_layers = 3;

    vefs::TransportedFields<dim> fields(triangulation, true, false, {});
    fields.setup_dofs();
    const auto velocity = vefs::velocity_components<dim>();
    const auto stress   = vefs::stress_components(fields);

    // Velocity component 0 constant, component 1 linear along the front;
    // the stress constant.
    const auto linear = [](const Point<dim> &p) {
      double f = 0.3 - 1.7 * p[1];
      if (dim == 3)
        f += 0.9 * p[dim - 1];
      return f;
    };
    const double velocity_constant = 2.5, stress_constant = -0.4;

    typename vefs::TransportedFields<dim>::VectorType known;
    fields.initialize_vector(known);
    for (const auto &node : fields.nodes())
      {
        const bool liquid   = node.point[0] <= front + 1e-12;
        known(node.dofs[0]) = liquid;
        fields.set_value(node, velocity[0], liquid ? velocity_constant : 7.);
        fields.set_value(node, velocity[1], liquid ? linear(node.point) : 7.);
        for (const unsigned int c : stress)
          fields.set_value(node, c, liquid ? stress_constant : 7.);
      }
    fields.finalize();

    std::vector<unsigned int> components = velocity;
    components.insert(components.end(), stress.begin(), stress.end());
    vefs::extend_flow_fields(fields, known, n_layers, components);

    double       constant_error = 0, linear_error = 0, beyond = 0;
    unsigned int wrong_flags = 0;
    for (const auto &node : fields.nodes())
      {
        const double layer    = (node.point[0] - front) / h;
        const bool   extended = layer > 0.5 && layer < n_layers + 0.5;
        const bool   flagged  = known(node.dofs[0]) != 0;
        if (flagged != (layer < n_layers + 0.5))
          ++wrong_flags;
        if (extended)
          {
            constant_error = std::max(constant_error,
                                      std::abs(fields.value(node, velocity[0]) -
                                               velocity_constant));
            for (const unsigned int c : stress)
              constant_error =
                std::max(constant_error,
                         std::abs(fields.value(node, c) - stress_constant));
            bool inside = true;
            for (unsigned int d = 1; d < dim; ++d)
              inside = inside && node.point[d] > n_layers * h - 1e-12 &&
                       node.point[d] < 1 - n_layers * h + 1e-12;
            if (inside)
              linear_error = std::max(linear_error,
                                      std::abs(fields.value(node, velocity[1]) -
                                               linear(node.point)));
          }
        else if (layer > n_layers + 0.5)
          for (const unsigned int c : components)
            beyond = std::max(beyond, std::abs(fields.value(node, c)));
      }
    const std::string label = std::to_string(dim) + "D, ";
    unit_test::check_below(out,
                           label + "constant, error in the layers",
                           Utilities::MPI::max(constant_error, comm),
                           1e-14);
    unit_test::check_below(out,
                           label + "linear along the front, error",
                           Utilities::MPI::max(linear_error, comm),
                           1e-13);
    unit_test::check_zero(out,
                          label + "largest value beyond the layers",
                          Utilities::MPI::max(beyond, comm));
    out << label
        << "nodes flagged wrongly: " << Utilities::MPI::sum(wrong_flags, comm)
        << '\n';
  }
} // namespace

int
main(int argc, char **argv)
{
  return unit_test::run(argc, argv, [](std::ostream &out) {
    check<2>(out);
    check<3>(out);
  });
}
