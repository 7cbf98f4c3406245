// The feet of the characteristics (characteristics.h) in a rigid rotation
// u = A (x - c), A = omega [n]_x, on a box mesh with hanging nodes, 1 and 2
// ranks (feet in cells of the other rank). The velocity is linear, so its
// Q1 interpolant, the Q1 level set psi = x_d and the recovered nodal
// gradients are exact, and each trace is a polynomial in theta = omega tau
// applied to x - c:
// - two-stage (midpoint) trace, through predict_level_set() with psi = x_d:
//   X = c + (I - tau A + tau^2 A^2 / 2)(x - c). Checked to round-off
//   (1e-13), and against the exactly rotated point c + exp(-tau A)(x - c):
//   there the error is (theta^3 / 6) r (1 + O(theta^2)), r the distance
//   from the axis, i.e. the ratio to theta^3 r / 6 lies within 0.01 of 1
//   for theta = 0.2.
// - four-stage trace, trace_back(): X = c + M (x - c) and dX/dx = M,
//   M = sum_{k<=4} (-tau A)^k / k!. Checked to round-off (1e-13); the
//   distance to the rotated point is below theta^5 r / 120 (times 1.01).
// Only nodes and points whose path stays inside the cavity (|x - c| <
// 0.8) are checked: outside, feet are moved back onto the walls.

#include "unit_test.h"

#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>

#include <vefs/compat/box_mesh_locator.h>
#include <vefs/stress/tensor_exponential.h>
#include <vefs/transport/characteristics.h>
#include <vefs/transport/nodal_gradients.h>

#include <iostream>

using namespace dealii;

namespace
{
  /** u = A (x - c). */
  template <int dim>
  class Rotation : public Function<dim>
  {
  public:
    Rotation(const Tensor<2, dim> &A, const Point<dim> &center)
      : Function<dim>(dim)
      , A(A)
      , center(center)
    {
    }

    double
    value(const Point<dim> &p, const unsigned int component) const override
    {
      return (A * (p - center))[component];
    }

  private:
    const Tensor<2, dim> A;
    const Point<dim>     center;
  };

  /** sum_{k <= order} (-tau A)^k / k!. */
  template <int dim>
  Tensor<2, dim>
  taylor(const Tensor<2, dim> &A, const double tau, const unsigned int order)
  {
    Tensor<2, dim> sum  = unit_symmetric_tensor<dim>();
    Tensor<2, dim> term = unit_symmetric_tensor<dim>();
    for (unsigned int k = 1; k <= order; ++k)
      {
        term = -tau / k * (term * A);
        sum += term;
      }
    return sum;
  }

  template <int dim>
  void
  check(std::ostream &out)
  {
    const MPI_Comm   comm  = MPI_COMM_WORLD;
    const double     omega = 2, tau = 0.1, theta = omega * tau;
    const double     radius = 0.8;
    const Point<dim> center = unit_test::filled<dim>(0.05);
    // The generator of the rotation about a tilted axis (the z axis in 2D).
    Tensor<2, dim> A;
    if constexpr (dim == 2)
      {
        A[0][1] = -omega;
        A[1][0] = omega;
      }
    else
      {
        Tensor<1, dim> n;
        n[0] = 1;
        n[1] = -2;
        n[2] = 2;
        n *= omega / n.norm();
        A[0][1] = -n[2];
        A[0][2] = n[1];
        A[1][0] = n[2];
        A[1][2] = -n[0];
        A[2][0] = -n[1];
        A[2][1] = n[0];
      }

    parallel::distributed::Triangulation<dim> triangulation(comm);
    const std::vector<unsigned int>           subdivisions =
      unit_test::make_box_with_finer_patch(triangulation);
    const BoundingBox<dim> cavity(
      std::make_pair(unit_test::filled<dim>(-1), unit_test::filled<dim>(1)));
    std::array<vefs::WallType, 6> walls;
    walls.fill(vefs::WallType::no_slip);
    const vefs::BoxMeshLocator<dim> locator(triangulation,
                                            cavity,
                                            subdivisions,
                                            walls);

    vefs::TransportedFields<dim> fields(triangulation, false, false, {});
    fields.setup_dofs();
    const Rotation<dim> velocity(A, center);

    const std::string name = std::to_string(dim) + "D, ";

    // Two stages: the foot's coordinate d as the predicted level set x_d.
    {
      const Tensor<2, dim> M = taylor(A, tau, 2);
      const Tensor<2, dim> R =
        vefs::tensor_exponential(Tensor<2, dim>(-tau * A));
      std::vector<Point<dim>> feet(fields.nodes().size());
      for (unsigned int d = 0; d < dim; ++d)
        {
          fields.interpolate(ScalarFunctionFromFunctionObject<dim>(
                               [d](const Point<dim> &p) { return p[d]; }),
                             velocity);
          const auto predicted = vefs::predict_level_set(fields, tau, locator);
          for (unsigned int i = 0; i < feet.size(); ++i)
            feet[i][d] = predicted(
              fields.nodes()[i]
                .dofs[vefs::TransportedFields<dim>::level_set_component]);
        }
      double       discrete_error = 0, ratio_error = 0;
      unsigned int n_checked = 0;
      for (unsigned int i = 0; i < feet.size(); ++i)
        {
          const Tensor<1, dim> r = fields.nodes()[i].point - center;
          if (r.norm() > radius)
            continue;
          ++n_checked;
          discrete_error =
            std::max(discrete_error, feet[i].distance(center + M * r));
          const double from_axis = (A * r).norm() / omega;
          if (from_axis > 0.1)
            ratio_error =
              std::max(ratio_error,
                       std::abs(feet[i].distance(center + R * r) /
                                  (std::pow(theta, 3) / 6 * from_axis) -
                                1));
        }
      unit_test::check_below(out,
                             name + "two-stage feet - discrete exact",
                             Utilities::MPI::max(discrete_error, comm),
                             1e-13);
      unit_test::check_below(
        out,
        name + "two-stage, |distance to rotated / (theta^3 r / 6) - 1|",
        Utilities::MPI::max(ratio_error, comm),
        0.01);
      out << name << "nodes checked: " << Utilities::MPI::sum(n_checked, comm)
          << '\n';
    }

    // Four stages, at points off the mesh's vertices.
    {
      fields.interpolate(Functions::ZeroFunction<dim>(), velocity);
      const auto velocity_gradient = vefs::recover_nodal_gradients(fields, dim);
      const Tensor<2, dim> M       = taylor(A, tau, 4);
      const Tensor<2, dim> R =
        vefs::tensor_exponential(Tensor<2, dim>(-tau * A));
      std::vector<Point<dim>> starts;
      // A lattice of points, the same on every rank; each rank traces its
      // own share.
      const unsigned int rank    = Utilities::MPI::this_mpi_process(comm);
      const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
      unsigned int       k       = 0;
      for (double x = -0.77; x < 0.8; x += 0.11)
        for (double y = -0.73; y < 0.8; y += 0.13)
          for (double z = dim == 3 ? -0.71 : 0; z < (dim == 3 ? 0.8 : 0.1);
               z += 0.17)
            {
              Point<dim> p;
              p[0] = x;
              p[1] = y;
              if (dim == 3)
                p[dim - 1] = z;
              if ((p - center).norm() < radius && k++ % n_ranks == rank)
                starts.push_back(p);
            }
      std::vector<Point<dim>>     feet = starts;
      std::vector<Tensor<2, dim>> jacobians(starts.size(),
                                            unit_symmetric_tensor<dim>());
      std::vector<double>         beyond_contact(starts.size());
      vefs::trace_back<dim>(fields,
                            velocity_gradient,
                            tau,
                            locator,
                            feet,
                            &jacobians,
                            beyond_contact);
      double foot_error = 0, jacobian_error = 0, rotation_ratio = 0;
      for (unsigned int i = 0; i < starts.size(); ++i)
        {
          const Tensor<1, dim> r = starts[i] - center;
          foot_error = std::max(foot_error, feet[i].distance(center + M * r));
          jacobian_error = std::max(jacobian_error, (jacobians[i] - M).norm());
          const double from_axis = (A * r).norm() / omega;
          if (from_axis > 0.1)
            rotation_ratio = std::max(rotation_ratio,
                                      feet[i].distance(center + R * r) /
                                        (std::pow(theta, 5) / 120 * from_axis));
        }
      unit_test::check_below(out,
                             name + "four-stage feet - discrete exact",
                             Utilities::MPI::max(foot_error, comm),
                             1e-13);
      unit_test::check_below(out,
                             name + "four-stage dX/dx - discrete exact",
                             Utilities::MPI::max(jacobian_error, comm),
                             1e-13);
      unit_test::check_below(
        out,
        name + "four-stage, distance to rotated / (theta^5 r / 120)",
        Utilities::MPI::max(rotation_ratio, comm),
        1.01);
      out << name << "points traced: "
          << Utilities::MPI::sum<unsigned int>(starts.size(), comm) << '\n';
    }
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
