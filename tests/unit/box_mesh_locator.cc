// BoxMeshLocator (box_mesh_locator.h) against deal.II on a box of unequal
// coarse cells, refined adaptively (cells of four levels, hanging nodes),
// 1 and 2 ranks. At a lattice of points off the cell faces:
// - locate() finds the cell GridTools::find_active_cell_around_point()
//   finds (compared where that cell is owned or a ghost; the points in
//   owned cells, summed over the ranks, are all points);
// - unit_point() equals MappingQ1::transform_real_to_unit_cell() to 1e-14;
// - locate_with_unit_point() finds locate()'s cell, with the same unit point
//   to 1e-14;
// - owner_rank() is this rank exactly for the points in owned cells and
//   another rank for the others.
// And fold_into_cavity() wraps a periodic direction and moves points back
// onto the other walls, a hair (1e-10 of the side) inside;
// gradient_beyond_contact_walls() equals central differences of
// f(fold_into_cavity(p)) beyond contact walls; touches_contact_wall() holds
// for exactly the cells with a boundary face on a contact wall.

#include "unit_test.h"

#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>

#include <vefs/compat/box_mesh_locator.h>

#include <iostream>

using namespace dealii;

namespace
{
  template <int dim>
  void
  check(std::ostream &out)
  {
    const MPI_Comm     comm = MPI_COMM_WORLD;
    const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
    // [0, 3] x [-1, 1] (x [0.5, 2]) in 3 x 2 (x 2) coarse cells.
    const std::vector<unsigned int> subdivisions =
      dim == 2 ? std::vector<unsigned int>{3, 2}
               : std::vector<unsigned int>{3, 2, 2};
    Point<dim> lower, upper;
    lower[0] = 0;
    upper[0] = 3;
    lower[1] = -1;
    upper[1] = 1;
    if (dim == 3)
      {
        lower[dim - 1] = 0.5;
        upper[dim - 1] = 2;
      }
    parallel::distributed::Triangulation<dim> triangulation(comm);
    GridGenerator::subdivided_hyper_rectangle(triangulation,
                                              subdivisions,
                                              lower,
                                              upper,
                                              true);
    triangulation.refine_global(1);
    // Refine around a point, three times: levels 1 to 4.
    Point<dim> focus;
    focus[0] = 1.1;
    focus[1] = 0.2;
    if (dim == 3)
      focus[dim - 1] = 1.3;
    for (unsigned int cycle = 0; cycle < 3; ++cycle)
      {
        for (const auto &cell : triangulation.active_cell_iterators())
          if (cell->is_locally_owned() &&
              cell->center().distance(focus) < 1.2 - 0.35 * cycle)
            cell->set_refine_flag();
        triangulation.execute_coarsening_and_refinement();
      }

    std::array<vefs::WallType, 6> walls;
    walls.fill(vefs::WallType::no_slip);
    walls[2] = walls[3] = vefs::WallType::periodic;
    const BoundingBox<dim>          cavity(std::make_pair(lower, upper));
    const vefs::BoxMeshLocator<dim> locator(triangulation,
                                            cavity,
                                            subdivisions,
                                            walls);
    const MappingQ1<dim>            mapping;

    // Steps that are no multiple of any cell size.
    const unsigned int n        = dim == 2 ? 41 : 13;
    unsigned int       n_points = 0, n_owned = 0, n_compared = 0;
    unsigned int       wrong_cell = 0, wrong_owner = 0, wrong_pair_cell = 0;
    double             unit_point_error = 0, pair_unit_point_error = 0;
    for (unsigned int k = 0; k < std::pow(n, dim); ++k)
      {
        Point<dim>   p;
        unsigned int rest = k;
        for (unsigned int d = 0; d < dim; ++d)
          {
            p[d] = lower[d] + (upper[d] - lower[d]) *
                                (0.0123 + 0.9731 * (rest % n) / (n - 1));
            rest /= n;
          }
        ++n_points;
        const auto located = locator.locate(p);
        const auto pair    = locator.locate_with_unit_point(p);
        if (pair.cell != located)
          ++wrong_pair_cell;
        const bool owned_here =
          !located->is_artificial() && located->is_locally_owned();
        n_owned += owned_here;
        if ((locator.owner_rank(p) == rank) != owned_here)
          ++wrong_owner;
        if (located->is_artificial())
          continue;
        const auto [cell, xi] =
          GridTools::find_active_cell_around_point(mapping, triangulation, p);
        ++n_compared;
        if (cell != located)
          ++wrong_cell;
        else
          {
            unit_point_error =
              std::max(unit_point_error,
                       xi.distance(
                         vefs::BoxMeshLocator<dim>::unit_point(located, p)));
            pair_unit_point_error =
              std::max(pair_unit_point_error, xi.distance(pair.unit_point));
          }
      }

    const std::string name = std::to_string(dim) + "D, ";
    out << name << "mesh levels: " << triangulation.n_global_levels()
        << ", points: " << n_points << ", in owned cells on all ranks: "
        << Utilities::MPI::sum(n_owned, comm) << '\n';
    out << name << "cells different from GridTools: "
        << Utilities::MPI::sum(wrong_cell, comm) << '\n';
    out << name
        << "wrong owner ranks: " << Utilities::MPI::sum(wrong_owner, comm)
        << '\n';
    unit_test::check_below(out,
                           name + "unit point - deal.II's",
                           Utilities::MPI::max(unit_point_error, comm),
                           1e-14);
    out << name << "locate_with_unit_point(), cells different from locate(): "
        << Utilities::MPI::sum(wrong_pair_cell, comm) << '\n';
    unit_test::check_below(out,
                           name + "its unit point - deal.II's",
                           Utilities::MPI::max(pair_unit_point_error, comm),
                           1e-14);
    // Compared at least at every point of the owned cells.
    out << name << "compared at all points of owned cells: "
        << (Utilities::MPI::sum(n_compared, comm) >= n_points ? "yes" : "no")
        << '\n';

    // y is periodic: 1.5 -> -0.5, -1.25 -> 0.75; x and z are clamped.
    Point<dim> outside, folded;
    outside[0] = -0.5;
    outside[1] = 1.5;
    folded[0]  = 3e-10;
    folded[1]  = -0.5;
    if (dim == 3)
      {
        outside[dim - 1] = 2.7;
        folded[dim - 1]  = 2 - 1.5e-10;
      }
    unit_test::check_below(out,
                           name + "fold_into_cavity error",
                           locator.fold_into_cavity(outside).distance(folded),
                           1e-15);
    // Beyond contact walls (x = 0, and z = 2 in 3D) the gradient of
    // f(fold_into_cavity(p)), against central differences (step 1e-6:
    // errors of order 1e-12 from the smooth f, 1e-10 from round-off).
    walls[0] = vefs::WallType::contact;
    if (dim == 3)
      walls[5] = vefs::WallType::contact;
    const vefs::BoxMeshLocator<dim> contact_locator(triangulation,
                                                    cavity,
                                                    subdivisions,
                                                    walls);
    const auto                      folded_f = [&](const Point<dim> &p) {
      const Point<dim> q = contact_locator.fold_into_cavity(p);
      return std::sin(q[0]) * std::cos(2 * q[1]) + q[dim - 1] * q[dim - 1];
    };
    const Point<dim> q = contact_locator.fold_into_cavity(outside);
    Tensor<1, dim>   grad_f;
    grad_f[0] = std::cos(q[0]) * std::cos(2 * q[1]);
    grad_f[1] = -2 * std::sin(q[0]) * std::sin(2 * q[1]);
    grad_f[dim - 1] += 2 * q[dim - 1];
    Tensor<1, dim> central_difference;
    for (unsigned int d = 0; d < dim; ++d)
      {
        const double h     = 1e-6;
        Point<dim>   plus  = outside;
        Point<dim>   minus = outside;
        plus[d] += h;
        minus[d] -= h;
        central_difference[d] = (folded_f(plus) - folded_f(minus)) / (2 * h);
      }
    unit_test::check_below(
      out,
      name + "gradient_beyond_contact_walls - central differences",
      (contact_locator.gradient_beyond_contact_walls(outside, grad_f) -
       central_difference)
        .norm(),
      1e-8);
    const Tensor<1, dim> gradient =
      contact_locator.gradient_beyond_contact_walls(outside, grad_f);
    out << name << "derivatives normal to the contact walls: " << gradient[0];
    if (dim == 3)
      out << ' ' << gradient[dim - 1];
    out << '\n';

    // touches_contact_wall() against deal.II's boundary faces: a cell has a
    // face at the boundary whose center lies on x = 0 (or z = 2).
    unsigned int n_touching = 0, n_different = 0;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          bool on_contact_wall = false;
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary())
              {
                const Point<dim> center = cell->face(f)->center();
                on_contact_wall =
                  on_contact_wall || std::abs(center[0]) < 1e-12 ||
                  (dim == 3 && std::abs(center[dim - 1] - 2) < 1e-12);
              }
          n_touching += on_contact_wall;
          n_different +=
            on_contact_wall != contact_locator.touches_contact_wall(cell);
        }
    out << name
        << "cells at contact walls: " << Utilities::MPI::sum(n_touching, comm)
        << ", touches_contact_wall() different: "
        << Utilities::MPI::sum(n_different, comm) << '\n';
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
