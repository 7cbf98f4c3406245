// CavityParameters::on_slip_or_contact_wall() (cavity.h) against deal.II's
// boundary ids: on the cavity's mesh (GridGenerator with colorized walls,
// boundary id 2d and 2d + 1 on the lower and upper wall of direction d) of
// unequal, non-dyadic coarse cells, refined adaptively, 1 and 2 ranks. Every
// vertex of an owned cell is on a slip or contact wall exactly when it is a
// vertex of a boundary face whose wall is slip or contact; the walls of the
// other types (no-slip, open, velocity) are not.

#include "unit_test.h"

#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/grid/grid_generator.h>

#include <vefs/base/cavity.h>

#include <iostream>
#include <set>

using namespace dealii;

namespace
{
  template <int dim>
  void
  check(std::ostream &out)
  {
    const MPI_Comm         comm = MPI_COMM_WORLD;
    vefs::CavityParameters cavity;
    cavity.cavity_lower        = {-0.2, 0.1, 0.05};
    cavity.cavity_upper        = {0.3, 0.37, 0.41};
    cavity.coarse_subdivisions = {3, 7, 3};
    cavity.wall_type           = {{vefs::WallType::no_slip,
                                   vefs::WallType::slip,
                                   vefs::WallType::contact,
                                   vefs::WallType::open,
                                   vefs::WallType::velocity,
                                   vefs::WallType::contact}};

    parallel::distributed::Triangulation<dim> triangulation(comm);
    std::vector<unsigned int>                 subdivisions(dim);
    for (unsigned int d = 0; d < dim; ++d)
      subdivisions[d] = cavity.coarse_subdivisions[d];
    GridGenerator::subdivided_hyper_rectangle(
      triangulation,
      subdivisions,
      vefs::to_point<dim>(cavity.cavity_lower),
      vefs::to_point<dim>(cavity.cavity_upper),
      true);
    // Cells of three levels, finest at a corner of the slip and contact
    // walls.
    Point<dim> corner = vefs::to_point<dim>(cavity.cavity_upper);
    corner[1]         = cavity.cavity_lower[1];
    for (unsigned int cycle = 0; cycle < 3; ++cycle)
      {
        for (const auto &cell : triangulation.active_cell_iterators())
          if (cell->is_locally_owned() &&
              cell->center().distance(corner) < 0.3 - 0.1 * cycle)
            cell->set_refine_flag();
        triangulation.execute_coarsening_and_refinement();
      }

    // The vertices of the boundary faces on slip and contact walls, as
    // deal.II numbers them.
    std::set<unsigned int> on_walls;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int f : cell->face_indices())
          if (cell->at_boundary(f))
            {
              const vefs::WallType type =
                cavity.wall_type[cell->face(f)->boundary_id()];
              if (type == vefs::WallType::slip ||
                  type == vefs::WallType::contact)
                for (const unsigned int v : cell->face(f)->vertex_indices())
                  on_walls.insert(cell->face(f)->vertex_index(v));
            }
    std::set<unsigned int> vertices, different;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          {
            const unsigned int index = cell->vertex_index(v);
            vertices.insert(index);
            if (cavity.on_slip_or_contact_wall(cell->vertex(v)) !=
                (on_walls.count(index) > 0))
              different.insert(index);
          }
    const std::string name = std::to_string(dim) + "D, ";
    out << name << "mesh levels: " << triangulation.n_global_levels()
        << ", vertices on slip and contact walls: "
        << (Utilities::MPI::sum(on_walls.size(), comm) > 0 ? "some" : "none")
        << ", different from deal.II's boundary faces: "
        << Utilities::MPI::sum(different.size(), comm) << '\n';
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
