// The second-order scheme's acceleration at the feet of the characteristics
// (characteristics.h): while the feet are traced the velocity slots hold
// u + tau/2 a, and u(X) = (u + tau/2 a)(X) - tau/2 a(X) only if a(X) is
// interpolated as the velocity is (doc/time_step_flow.md, "The second-order
// scheme"). On a box mesh with hanging nodes, 1 and 2 ranks, a smooth
// field f (sines: neither Q1 nor Hermite interpolation reproduces it) is
// put into every acceleration component and, scaled by s on a uniform U,
// into every velocity component, u = U + s f, and one advection step is
// made with each velocity interpolation (linear, cubic, limited cubic): the
// velocity at the feet is the reference, and each acceleration component
// must equal (u - U) / s there to round-off. That this can fail: the Q1
// and the cubic interpolants of f at the feet differ by more than 1e-3 (the
// acceleration was Q1 with a cubic velocity).

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
  /** The scale s of f in the velocity. */
  constexpr double velocity_scale = 0.1;

  /** u = U + s f in every component. */
  template <int dim>
  class ScaledOnUniform : public Function<dim>
  {
  public:
    ScaledOnUniform(const Function<dim> &f, const Tensor<1, dim> &uniform)
      : Function<dim>(dim)
      , f(f)
      , uniform(uniform)
    {
    }

    double
    value(const Point<dim> &p, const unsigned int component) const override
    {
      return uniform[component] + velocity_scale * f.value(p, 0);
    }

  private:
    const Function<dim> &f;
    const Tensor<1, dim> uniform;
  };

  /** (u - U) / s and the acceleration components after one step. */
  template <int dim>
  struct Advected
  {
    std::vector<std::array<double, dim>> velocity_part;
    std::vector<std::array<double, dim>> acceleration;
  };

  template <int dim>
  Advected<dim>
  advect(const parallel::distributed::Triangulation<dim> &triangulation,
         const vefs::BoxMeshLocator<dim>                 &locator,
         const vefs::VelocityInterpolation                velocity)
  {
    vefs::TransportedFields<dim> fields(triangulation, false, true, {});
    fields.setup_dofs();
    const unit_test::Smooth<dim> f(1, 0.3);
    Tensor<1, dim>               uniform;
    for (unsigned int d = 0; d < dim; ++d)
      uniform[d] = 0.3 - 0.2 * d;
    fields.interpolate(f, ScaledOnUniform<dim>(f, uniform));
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
    parameters.level_set_interpolation = vefs::LevelSetInterpolation::linear;
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
        const Tensor<1, dim>    u = fields.velocity(node);
        const Tensor<1, dim>    a = fields.acceleration(node);
        std::array<double, dim> velocity_part, acceleration;
        for (unsigned int d = 0; d < dim; ++d)
          {
            velocity_part[d] = (u[d] - uniform[d]) / velocity_scale;
            acceleration[d]  = a[d];
          }
        advected.velocity_part.push_back(velocity_part);
        advected.acceleration.push_back(acceleration);
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
    using V                = vefs::VelocityInterpolation;
    const std::vector<std::pair<std::string, V>> cases = {{"linear", V::linear},
                                                          {"cubic", V::cubic},
                                                          {"limited cubic",
                                                           V::limited_cubic}};
    std::vector<Advected<dim>>                   results;
    for (const auto &[label, velocity] : cases)
      {
        results.push_back(advect<dim>(triangulation, locator, velocity));
        const Advected<dim> &r     = results.back();
        double               error = 0;
        for (unsigned int i = 0; i < r.acceleration.size(); ++i)
          for (unsigned int d = 0; d < dim; ++d)
            error =
              std::max(error,
                       std::abs(r.acceleration[i][d] - r.velocity_part[i][d]));
        unit_test::check_below(out,
                               name + label +
                                 ": acceleration - (u - U) / s at the feet",
                               Utilities::MPI::max(error, comm),
                               1e-13);
      }
    double difference = 0;
    for (unsigned int i = 0; i < results[0].acceleration.size(); ++i)
      difference = std::max(difference,
                            std::abs(results[0].acceleration[i][0] -
                                     results[1].acceleration[i][0]));
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
