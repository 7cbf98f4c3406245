// The contact set of the walls (contact_walls.h, design section 4), through
// the flow step's own iteration (StokesStep::solve() and update_contact()
// as the simulator calls them). Two separate blocks of liquid rest on a
// contact floor, 2D, no gravity: the left one is thrown at the floor
// (u* = (0, -1)), the right one away from it (u* = (0, 1)). They do not
// touch, so each is a problem of its own with a known answer: every wet
// floor node of the left block presses (stays in contact, u_y = 0 there),
// every one of the right block pulls away (is released, and its velocity
// then leaves the wall, u_y > 0). The contact length is then exactly the
// floor faces of the left block's liquid cells; the floor pushes the
// left block up (force > 0), and its power at the mid-step velocity
// (u + u*)/2 = (0, -1/2) of the nodes in contact is -force / 2. The set's
// state for a checkpoint
// (StokesStep::contact_state()) holds the released nodes, from which a
// resumed step starts settled. 1 and 2 ranks.
// Tolerance: |u_y| below 1e-6 in contact (solver tolerance 1e-10 on a
// velocity of order 1, the contact rows are identities), u_y above 0.1
// where released; the power within 1e-5 of the force (|u_y| in contact).

#include "unit_test.h"

#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/grid/grid_generator.h>

#include <vefs/core/parameters.h>
#include <vefs/flow/stokes_step.h>
#include <vefs/transport/liquid_domain.h>

#include <cstdlib>
#include <iostream>
#include <set>

using namespace dealii;

namespace
{
  /** u* = (0, -1) left of x = 0, (0, 1) right of it. */
  class ThrownBlocks : public Function<2>
  {
  public:
    ThrownBlocks()
      : Function<2>(2)
    {
    }

    double
    value(const Point<2> &p, const unsigned int component) const override
    {
      return component == 0 ? 0. : (p[0] < 0 ? -1. : 1.);
    }
  };

  void
  check(std::ostream &out)
  {
    const MPI_Comm   comm = MPI_COMM_WORLD;
    vefs::Parameters parameters;
    parameters.dimension                  = 2;
    parameters.cavity.cavity_lower        = {-1, 0};
    parameters.cavity.cavity_upper        = {1, 1};
    parameters.cavity.coarse_subdivisions = {2, 1};
    parameters.cavity.wall_type.fill(vefs::WallType::no_slip);
    parameters.cavity.wall_type[2]      = vefs::WallType::contact;
    parameters.material.gravity         = {0, 0};
    parameters.material.relaxation_time = 0;
    parameters.flow.flow_level_offset   = 0;
    parameters.solver.solver_tolerance  = 1e-10;

    parallel::distributed::Triangulation<2> triangulation(comm);
    GridGenerator::subdivided_hyper_rectangle(triangulation,
                                              {2, 1},
                                              Point<2>(-1, 0),
                                              Point<2>(1, 1),
                                              true);
    triangulation.refine_global(4);

    // Blocks |x -+ 0.5| < 0.27, y < 0.27 (edges inside cells).
    vefs::TransportedFields<2> fields(triangulation, false, false, {});
    fields.setup_dofs();
    fields.interpolate(
      ScalarFunctionFromFunctionObject<2>([](const Point<2> &p) {
        return std::max(std::abs(std::abs(p[0]) - 0.5) - 0.27, p[1] - 0.27);
      }),
      ThrownBlocks());
    const vefs::LiquidDomain<2> domain(fields);

    const vefs::Rheology<2> rheology(parameters.material,
                                     parameters.stress,
                                     parameters.time.max_strain_per_step,
                                     parameters.time.second_order);
    vefs::StokesStep<2> flow(parameters.flow_step(), rheology, triangulation);
    const double        tau = 0.01;
    flow.setup(domain, tau);
    flow.assemble(fields, tau);
    unsigned int n_solves = 0;
    bool         changed  = true;
    for (; changed && n_solves < 10; ++n_solves)
      {
        flow.solve(parameters.solver.solver_tolerance);
        changed = flow.update_contact(fields, tau);
      }
    out << "contact set settled: " << (changed ? "no" : "yes") << '\n';

    // The normal velocity at the floor's nodes of liquid cells, owned.
    const auto                       &dof_handler = flow.get_dof_handler();
    const auto                       &solution    = flow.get_solution();
    std::set<types::global_dof_index> seen;
    unsigned int                      n_left = 0, n_left_in_contact = 0;
    unsigned int                      n_right = 0, n_right_leaving = 0;
    double                            largest_left = 0, smallest_right = 1e300;
    double                            expected_length = 0;
    const IndexSet                    owned = dof_handler.locally_owned_dofs();
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && cell->get_fe().n_dofs_per_cell() > 0)
        for (const unsigned int f : cell->face_indices())
          if (cell->at_boundary(f) && cell->face(f)->boundary_id() == 2)
            {
              if (cell->center()[0] < 0)
                expected_length += cell->face(f)->measure();
              for (const unsigned int v : cell->face(f)->vertex_indices())
                {
                  const auto dof =
                    cell->face(f)->vertex_dof_index(v,
                                                    1,
                                                    cell->active_fe_index());
                  if (!owned.is_element(dof) || !seen.insert(dof).second)
                    continue;
                  const double u_y = solution(dof);
                  if (cell->face(f)->vertex(v)[0] < 0)
                    {
                      ++n_left;
                      n_left_in_contact += std::abs(u_y) < 1e-6;
                      largest_left = std::max(largest_left, std::abs(u_y));
                    }
                  else
                    {
                      ++n_right;
                      n_right_leaving += u_y > 0.1;
                      smallest_right = std::min(smallest_right, u_y);
                    }
                }
            }
    // The margins of the tolerances, for choosing them.
    if (std::getenv("VEFS_UNIT_VERBOSE"))
      std::cerr << "largest |u_y| left " << largest_left
                << ", smallest u_y right " << smallest_right << '\n';
    out << "left block: wet floor nodes " << Utilities::MPI::sum(n_left, comm)
        << ", in contact (u_y = 0) "
        << Utilities::MPI::sum(n_left_in_contact, comm) << '\n';
    out << "right block: wet floor nodes " << Utilities::MPI::sum(n_right, comm)
        << ", leaving the wall (u_y > 0) "
        << Utilities::MPI::sum(n_right_leaving, comm) << '\n';
    expected_length = Utilities::MPI::sum(expected_length, comm);
    unit_test::check_below(out,
                           "contact length - left block's wet floor",
                           std::abs(flow.contact_measure() - expected_length),
                           1e-12);
    out << "contact force positive: "
        << (flow.contact_force() > 0 ? "yes" : "no") << '\n';
    // The energy budget's work of the walls: at the unknowns in contact u = 0
    // and u* = (0, -1), so the power at (u + u*)/2 is -force / 2.
    unit_test::check_below(out,
                           "contact power + force / 2, relative to the force",
                           std::abs(flow.contact_power(fields) +
                                    0.5 * flow.contact_force()) /
                             flow.contact_force(),
                           1e-5);

    // The state a checkpoint keeps: the released nodes, those of the right
    // block's wet floor. A flow step resumed from it starts with the settled
    // set (its first update changes nothing); a fresh one starts with every
    // wet node in contact and must release the right block's.
    const std::vector<Point<2>> state     = flow.contact_state();
    bool                        all_right = true;
    for (const Point<2> &node : state)
      all_right = all_right && node[0] > 0 && node[1] == 0;
    out << "saved state: " << state.size()
        << " released nodes, all on the right block's floor: "
        << (all_right ? "yes" : "no") << '\n';
    const auto first_update_changes = [&](const bool resumed) {
      vefs::StokesStep<2> next(parameters.flow_step(), rheology, triangulation);
      if (resumed)
        next.resume_contact(state);
      next.setup(domain, tau);
      next.assemble(fields, tau);
      next.solve(parameters.solver.solver_tolerance);
      return next.update_contact(fields, tau);
    };
    out << "resumed from it: first update changes the set: "
        << (first_update_changes(true) ? "yes" : "no") << '\n';
    out << "not resumed: first update changes the set: "
        << (first_update_changes(false) ? "yes" : "no") << '\n';
  }
} // namespace

int
main(int argc, char **argv)
{
  return unit_test::run(argc, argv, [](std::ostream &out) { check(out); });
}
