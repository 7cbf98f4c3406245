// Evaluation of the fields at arbitrary points against deal.II's
// VectorTools::point_value() (evaluated on the rank owning the point), on
// a mesh with hanging nodes, 2D and 3D, 1 and 2 ranks:
// - probe_velocity() (postprocessing.h), the velocity on every rank;
// - level_set_at() (characteristics.h) with linear interpolation, for
//   points anywhere (those in cells of another rank are evaluated there).
// Both are Q1 interpolation written out, so they agree with deal.II's
// FEValues to round-off: below 1e-13 (values of order 1).

#include "unit_test.h"

#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/numerics/vector_tools_point_value.h>

#include <vefs/io/postprocessing.h>
#include <vefs/transport/characteristics.h>

#include <iostream>

using namespace dealii;

namespace
{
  template <int dim>
  void
  check(std::ostream &out)
  {
    const MPI_Comm comm = MPI_COMM_WORLD;
    Point<dim>     lower, upper;
    for (unsigned int d = 0; d < dim; ++d)
      {
        lower[d] = -1;
        upper[d] = 1;
      }
    const std::vector<unsigned int>           subdivisions(dim, 2);
    parallel::distributed::Triangulation<dim> triangulation(comm);
    GridGenerator::subdivided_hyper_rectangle(triangulation,
                                              subdivisions,
                                              lower,
                                              upper,
                                              true);
    triangulation.refine_global(2);
    for (unsigned int cycle = 0; cycle < 2; ++cycle)
      {
        for (const auto &cell : triangulation.active_cell_iterators())
          if (cell->is_locally_owned() &&
              cell->center()[0] + cell->center()[1] < 0.5 - 0.5 * cycle)
            cell->set_refine_flag();
        triangulation.execute_coarsening_and_refinement();
      }
    std::array<vefs::WallType, 6> walls;
    walls.fill(vefs::WallType::no_slip);
    const vefs::BoxMeshLocator<dim> locator(triangulation,
                                            BoundingBox<dim>(
                                              std::make_pair(lower, upper)),
                                            subdivisions,
                                            walls);

    vefs::TransportedFields<dim> fields(triangulation, false, false, {});
    fields.setup_dofs();
    fields.interpolate(unit_test::Smooth<dim>(1, 0.3),
                       unit_test::Smooth<dim>(dim, -0.2));

    // The same points on every rank.
    std::vector<Point<dim>> points;
    const unsigned int      n = dim == 2 ? 15 : 6;
    for (unsigned int k = 0; k < std::pow(n, dim); ++k)
      {
        Point<dim>   p;
        unsigned int rest = k;
        for (unsigned int d = 0; d < dim; ++d)
          {
            p[d] = -0.987 + 1.97 * (rest % n) / (n - 1) + 0.001 * d;
            rest /= n;
          }
        points.push_back(p);
      }

    // deal.II's values, from the rank that owns each point's cell (it
    // throws on the others: the point is not in an owned cell there).
    const unsigned int        n_values = dim + 1;
    std::vector<double>       reference(points.size() * n_values);
    std::vector<unsigned int> n_owners(points.size());
    for (unsigned int i = 0; i < points.size(); ++i)
      {
        Vector<double> values(fields.n_components);
        try
          {
            VectorTools::point_value(fields.mapping,
                                     fields.dof_handler,
                                     fields.vector(),
                                     points[i],
                                     values);
          }
        catch (const ExceptionBase &)
          {
            continue;
          }
        n_owners[i] = 1;
        for (unsigned int c = 0; c < n_values; ++c)
          reference[i * n_values + c] = values[c];
      }
    Utilities::MPI::sum(reference, comm, reference);
    Utilities::MPI::sum(n_owners, comm, n_owners);

    // The linear level set reads no gradient.
    const auto level_sets =
      vefs::level_set_at(fields,
                         vefs::LevelSetGradient<dim>(),
                         points,
                         locator,
                         vefs::LevelSetInterpolation::linear);
    double       velocity_error = 0, level_set_error = 0;
    unsigned int n_not_one_owner = 0;
    for (unsigned int i = 0; i < points.size(); ++i)
      {
        n_not_one_owner += n_owners[i] != 1;
        const Tensor<1, dim> u =
          vefs::probe_velocity(fields, locator, points[i], 1.).velocity;
        for (unsigned int d = 0; d < dim; ++d)
          velocity_error =
            std::max(velocity_error,
                     std::abs(u[d] - reference[i * n_values + d]));
        level_set_error = std::max(level_set_error,
                                   std::abs(level_sets[i].first -
                                            reference[i * n_values + dim]));
      }
    const std::string name = std::to_string(dim) + "D, ";
    out << name << "points: " << points.size()
        << ", owned by other than one rank: " << n_not_one_owner << '\n';
    unit_test::check_below(out,
                           name + "probe_velocity - point_value",
                           Utilities::MPI::max(velocity_error, comm),
                           1e-13);
    unit_test::check_below(out,
                           name + "level_set_at - point_value",
                           Utilities::MPI::max(level_set_error, comm),
                           1e-13);
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
