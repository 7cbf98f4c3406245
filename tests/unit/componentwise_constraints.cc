// make_componentwise_constraints() (compat/componentwise_constraints.h)
// against the deal.II routines it replaces,
// DoFTools::make_hanging_node_constraints() and
// make_periodicity_constraints() on the DoFHandler of FE_Q(1)^5: on a 2D
// mesh periodic in x and a 3D one, each refined locally (hanging nodes,
// also at the periodic walls in 2D), the closed constraints must hold the
// same lines with the same entries and weights, exactly. 1 and 2 ranks.

#include "unit_test.h"

#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>

#include <vefs/compat/componentwise_constraints.h>

#include <iostream>

using namespace dealii;

namespace
{
  template <int dim>
  void
  check(std::ostream &out, const bool periodic)
  {
    parallel::distributed::Triangulation<dim> triangulation(MPI_COMM_WORLD);
    GridGenerator::hyper_cube(triangulation, 0, 1, true);
    std::vector<unsigned int> periodic_directions;
    if (periodic)
      {
        std::vector<GridTools::PeriodicFacePair<
          typename parallel::distributed::Triangulation<dim>::cell_iterator>>
          pairs;
        GridTools::collect_periodic_faces(triangulation, 0, 1, 0, pairs);
        triangulation.add_periodicity(pairs);
        periodic_directions.push_back(0);
      }
    triangulation.refine_global(2);
    // Refine a corner region twice: hanging nodes inside and, with the
    // periodic x walls, across them.
    for (unsigned int cycle = 0; cycle < 2; ++cycle)
      {
        for (const auto &cell : triangulation.active_cell_iterators())
          if (cell->is_locally_owned() && cell->center()[0] < 0.3 &&
              cell->center()[1] < 0.6)
            cell->set_refine_flag();
        triangulation.execute_coarsening_and_refinement();
      }

    const FESystem<dim> fe(FE_Q<dim>(1), 5);
    DoFHandler<dim>     dof_handler(triangulation);
    dof_handler.distribute_dofs(fe);
    IndexSet relevant;
    DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);

    AffineConstraints<double> expected(relevant);
    DoFTools::make_hanging_node_constraints(dof_handler, expected);
    for (const unsigned int d : periodic_directions)
      DoFTools::make_periodicity_constraints(dof_handler,
                                             2 * d,
                                             2 * d + 1,
                                             d,
                                             expected);
    expected.close();

    AffineConstraints<double> computed;
    vefs::make_componentwise_constraints(dof_handler,
                                         periodic_directions,
                                         relevant,
                                         computed);

    unsigned int n_different = 0, n_lines = 0;
    for (const auto i : relevant)
      {
        if (expected.is_constrained(i) != computed.is_constrained(i))
          {
            ++n_different;
            continue;
          }
        if (!expected.is_constrained(i))
          continue;
        ++n_lines;
        const auto &a = *expected.get_constraint_entries(i);
        const auto &b = *computed.get_constraint_entries(i);
        if (a != b ||
            expected.get_inhomogeneity(i) != computed.get_inhomogeneity(i))
          ++n_different;
      }
    const MPI_Comm comm = MPI_COMM_WORLD;
    out << dim << "D" << (periodic ? ", periodic in x" : "")
        << ": constrained degrees of freedom (summed over ranks' relevant "
           "sets) "
        << (Utilities::MPI::sum(n_lines, comm) > 0 ? "some" : "NONE")
        << ", lines differing from deal.II's: "
        << Utilities::MPI::sum(n_different, comm) << '\n';
  }
} // namespace

int
main(int argc, char **argv)
{
  return unit_test::run(argc, argv, [](std::ostream &out) {
    check<2>(out, false);
    check<2>(out, true);
    check<3>(out, false);
  });
}
