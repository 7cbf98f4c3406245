// VertexFieldTransfer (vertex_field_transfer.h) against deal.II's
// parallel::distributed::SolutionTransfer through one mesh change that
// refines some cells and coarsens others, on a mesh with hanging nodes,
// 2D and 3D, 1 and 2 ranks. Carried: every component of the fields (with
// stress) and the dim gradient slots of the level set gradient. Both
// interpolate Q1 onto children and take the parent's values at its
// children's corners, so the owned entries must agree after the
// constraints are distributed, up to the order of the sums (relative
// difference below 1e-14; seen: 0).

#include "unit_test.h"

#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/distributed/solution_transfer.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/grid/grid_generator.h>

#include <vefs/fields/vertex_field_transfer.h>

#include <iostream>

using namespace dealii;

namespace
{
  template <int dim>
  void
  check(std::ostream &out)
  {
    using VectorType = typename vefs::TransportedFields<dim>::VectorType;
    const MPI_Comm                            comm = MPI_COMM_WORLD;
    parallel::distributed::Triangulation<dim> triangulation(comm);
    GridGenerator::hyper_cube(triangulation, -1, 1, true);
    triangulation.refine_global(dim == 2 ? 3 : 2);
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned() && cell->center()[0] > 0)
        cell->set_refine_flag();
    triangulation.execute_coarsening_and_refinement();

    vefs::TransportedFields<dim> fields(triangulation, true, {});
    fields.setup_dofs();
    const unsigned int n_stress =
      vefs::TransportedFields<dim>::n_stress_components;
    fields.interpolate(
      unit_test::Smooth<dim>(1, 0.5),
      unit_test::Smooth<dim>(dim, -0.3),
      std::make_unique<unit_test::Smooth<dim>>(n_stress, 2.).get());
    // The gradient slots hold something else than a gradient here: any
    // values do.
    for (const auto &node : fields.nodes())
      for (unsigned int d = 0; d < dim; ++d)
        fields.mutable_level_set_gradient_vector()(node.dofs[d]) =
          std::cos(3 * node.point[d] + d) * (1 + node.point[0]);
    fields.finalize();

    // Refine the fine cells at y > 0.2, coarsen those at y < -0.2 (p4est
    // coarsens whole families only), refine once more at the coarse cells
    // near x = -0.5.
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const Point<dim> c = cell->center();
          if (c[0] > 0 && c[1] > 0.2)
            cell->set_refine_flag();
          else if (c[0] > 0 && c[1] < -0.2)
            cell->set_coarsen_flag();
          else if (std::abs(c[0] + 0.5) < 0.2)
            cell->set_refine_flag();
        }
    triangulation.prepare_coarsening_and_refinement();
    unsigned int n_refined = 0, n_coarsened = 0;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          n_refined += cell->refine_flag_set() ? 1 : 0;
          n_coarsened += cell->coarsen_flag_set() ? 1 : 0;
        }

    std::vector<unsigned int> all_components, gradient_components;
    for (unsigned int c = 0; c < fields.n_components; ++c)
      all_components.push_back(c);
    for (unsigned int d = 0; d < dim; ++d)
      gradient_components.push_back(d);
    vefs::VertexFieldTransfer<dim> transfer(
      triangulation,
      fields,
      {{&fields.mutable_vector(), all_components},
       {&fields.mutable_level_set_gradient_vector(), gradient_components}});
    parallel::distributed::SolutionTransfer<dim, VectorType> reference(
      fields.dof_handler);
    reference.prepare_for_coarsening_and_refinement(
      std::vector<const VectorType *>{
        &fields.mutable_vector(),
        &fields.mutable_level_set_gradient_vector()});
    triangulation.execute_coarsening_and_refinement();

    fields.setup_dofs();
    VectorType mine_fields, mine_gradient, their_fields, their_gradient;
    for (VectorType *vector :
         {&mine_fields, &mine_gradient, &their_fields, &their_gradient})
      {
        fields.initialize_vector(*vector);
        vector->zero_out_ghost_values();
      }
    transfer.unpack(fields, {&mine_fields, &mine_gradient});
    std::vector<VectorType *> theirs{&their_fields, &their_gradient};
    reference.interpolate(theirs);
    for (VectorType *vector :
         {&mine_fields, &mine_gradient, &their_fields, &their_gradient})
      {
        vector->update_ghost_values();
        fields.distribute_constraints(*vector);
      }

    // Relative to the largest entry.
    double difference = 0, largest = 0;
    for (const auto index : fields.owned_dofs)
      {
        largest = std::max(largest, std::abs(their_fields(index)));
        difference =
          std::max(difference,
                   std::abs(mine_fields(index) - their_fields(index)));
      }
    for (const auto &node : fields.nodes())
      for (unsigned int d = 0; d < dim; ++d)
        difference = std::max(difference,
                              std::abs(mine_gradient(node.dofs[d]) -
                                       their_gradient(node.dofs[d])));

    const std::string name = std::to_string(dim) + "D, ";
    out << name << "cells refined: " << Utilities::MPI::sum(n_refined, comm)
        << ", coarsened: " << Utilities::MPI::sum(n_coarsened, comm)
        << ", cells after: " << triangulation.n_global_active_cells() << '\n';
    unit_test::check_below(out,
                           name + "difference from SolutionTransfer, relative",
                           Utilities::MPI::max(difference, comm) /
                             Utilities::MPI::max(largest, comm),
                           1e-14);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ostringstream               text;
  check<2>(text);
  check<3>(text);
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    std::cout << text.str();
}
