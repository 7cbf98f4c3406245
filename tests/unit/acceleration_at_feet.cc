// The second-order scheme's acceleration at the feet of the characteristics
// (characteristics.h): while the feet are traced the velocity slots hold
// u + tau/2 a, and u(X) = (u + tau/2 a)(X) - tau/2 a(X) only if a(X) is
// interpolated as the velocity is (doc/time_step_flow.md, "The second-order
// scheme"). On a box mesh with hanging nodes, 1 and 2 ranks, the same
// smooth field f (sines: neither Q1 nor Hermite interpolation reproduces
// it) is put into the level set and into every acceleration component, the
// velocity is uniform, and one advection step is made with the level set
// and the velocity interpolated alike (linear, cubic, limited cubic): the
// level set, which those interpolations are known to carry, is the
// reference, and each acceleration component must equal it to round-off.
// That this can fail: the Q1 and the cubic interpolants of f at the feet
// differ by more than 1e-3 (the acceleration was Q1 with a cubic velocity).

#include "unit_test.h"

#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>

#include <vefs/compat/box_mesh_locator.h>
#include <vefs/transport/characteristics.h>
#include <vefs/transport/level_set_gradient.h>

#include <iostream>

using namespace dealii;

namespace
{
  /** The level set and the acceleration components after one step. */
  template <int dim>
  struct Advected
  {
    std::vector<double>                  level_set;
    std::vector<std::array<double, dim>> acceleration;
  };

  template <int dim>
  Advected<dim>
  advect(const parallel::distributed::Triangulation<dim> &triangulation,
         const vefs::BoxMeshLocator<dim>                 &locator,
         const vefs::LevelSetInterpolation                level_set,
         const vefs::VelocityInterpolation                velocity)
  {
    vefs::TransportedFields<dim> fields(triangulation, false, true, {});
    fields.setup_dofs();
    const unit_test::Smooth<dim> f(1, 0.3);
    Tensor<1, dim>               uniform;
    for (unsigned int d = 0; d < dim; ++d)
      uniform[d] = 0.3 - 0.2 * d;
    fields.interpolate(f,
                       Functions::ConstantFunction<dim>(
                         std::vector<double>(uniform.begin_raw(),
                                             uniform.end_raw())));
    for (const auto &node : fields.nodes())
      {
        Tensor<1, dim> a;
        for (unsigned int d = 0; d < dim; ++d)
          a[d] = f.value(node.point, 0);
        fields.set_acceleration(node, a);
      }
    fields.finalize();

    vefs::LevelSetGradient<dim> level_set_gradient;
    level_set_gradient.reinit(fields);
    vefs::TransportParameters parameters;
    parameters.level_set_interpolation = level_set;
    parameters.velocity_interpolation  = velocity;
    parameters.resolve(false, false, false, dim);
    const vefs::FootInterpolation interpolation(parameters, false, 1.);
    // The feet 0.03 away: a quarter to half of a cell.
    vefs::advect_along_characteristics(fields,
                                       level_set_gradient,
                                       0.1,
                                       locator,
                                       interpolation);

    Advected<dim> advected;
    for (const auto &node : fields.nodes())
      {
        advected.level_set.push_back(fields.level_set(node));
        const Tensor<1, dim>    a = fields.acceleration(node);
        std::array<double, dim> components;
        for (unsigned int d = 0; d < dim; ++d)
          components[d] = a[d];
        advected.acceleration.push_back(components);
      }
    return advected;
  }

  template <int dim>
  void
  check(std::ostream &out)
  {
    const MPI_Comm                            comm = MPI_COMM_WORLD;
    parallel::distributed::Triangulation<dim> triangulation(comm);
    const std::vector<unsigned int>           subdivisions =
      unit_test::make_box_with_finer_patch(triangulation);
    std::array<vefs::WallType, 6> walls;
    walls.fill(vefs::WallType::no_slip);
    const vefs::BoxMeshLocator<dim> locator(
      triangulation,
      BoundingBox<dim>(
        std::make_pair(unit_test::filled<dim>(-1), unit_test::filled<dim>(1))),
      subdivisions,
      walls);

    const std::string name = std::to_string(dim) + "D, ";
    using L                = vefs::LevelSetInterpolation;
    using V                = vefs::VelocityInterpolation;
    const std::vector<std::tuple<std::string, L, V>> cases = {
      {"linear", L::linear, V::linear},
      {"cubic", L::cubic, V::cubic},
      {"limited cubic", L::limited_cubic, V::limited_cubic}};
    std::vector<Advected<dim>> results;
    for (const auto &[label, level_set, velocity] : cases)
      {
        results.push_back(
          advect<dim>(triangulation, locator, level_set, velocity));
        const Advected<dim> &r     = results.back();
        double               error = 0;
        for (unsigned int i = 0; i < r.level_set.size(); ++i)
          for (unsigned int d = 0; d < dim; ++d)
            error =
              std::max(error, std::abs(r.acceleration[i][d] - r.level_set[i]));
        unit_test::check_below(out,
                               name + label +
                                 ": acceleration - level set at the feet",
                               Utilities::MPI::max(error, comm),
                               1e-13);
      }
    double difference = 0;
    for (unsigned int i = 0; i < results[0].level_set.size(); ++i)
      difference =
        std::max(difference,
                 std::abs(results[0].level_set[i] - results[1].level_set[i]));
    out << name << "Q1 and cubic interpolants of f at the feet differ by more "
        << "than 1e-3: "
        << (Utilities::MPI::max(difference, comm) > 1e-3 ? "yes" : "NO")
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
