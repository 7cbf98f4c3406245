// GhostPenalty (ghost_penalty.h) against its weak form in closed form. The
// unit square, h = 1/16, the liquid below y = 0.41: the row of cells
// 0.375 < y < 0.4375 is cut. The penalised faces are those of cut cells
// with liquid beyond: the 15 faces between the cut cells, each once, and the
// 16 faces below them; not those to the empty row above, 31 in all. On each
// face the velocity term is gamma (mu + rho h^2/tau) h int_F [d_n u].[d_n v],
// the pressure term -gamma tau_K h int_F [d_n p][d_n q] and the Schur term
// gamma (tau/rho + tau_K) h int_F [d_n p][d_n q] (gamma = 0.1, both sides
// of a face between cut cells with half of it).
// - Fields linear in x and y: all three forms vanish (a liquid at rest
//   stays at rest): below 1e-10 of the quadratic field's.
// - x^2 in one component: its Q1 interpolant's x-derivative jumps by 2h
//   across each vertical face and not across the horizontal ones, so each
//   form is 15 (weight) (2h)^2 h: to 1e-10, velocity and pressure alike.
// - The faces visited: 31 (summed over the ranks, 1 and 2 ranks).
// The forms are sums of products of nodal values whose terms are about
// 1/h^2 = 256 times the result: round-off 1e-16 x 256 x the few dozen
// products of a face is 1e-12 to 1e-11 (measured up to 6e-12); hence
// 1e-10. A wrong weight or a non-vanishing linear form would be off by
// order one.

#include "flow_step_setup.h"
#include "unit_test.h"

#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>

#include <vefs/flow/ghost_penalty.h>

#include <functional>
#include <iostream>

using namespace dealii;

namespace
{
  /** The three forms of all visited faces for a field, and the face count. */
  struct Forms
  {
    double       velocity = 0, pressure = 0, schur = 0;
    unsigned int faces = 0;
  };

  template <int dim>
  Forms
  forms(vefs::GhostPenalty<dim> &penalty,
        const DoFHandler<dim>   &dof_handler,
        const std::function<double(const Point<dim> &, unsigned int)> &field)
  {
    // The field at every dof: the Q1 interpolant of each component.
    std::map<types::global_dof_index, double>       values;
    std::map<types::global_dof_index, unsigned int> component_of;
    const FiniteElement<dim>                       &fe = dof_handler.get_fe();
    std::vector<types::global_dof_index> cell_dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (!cell->is_artificial())
        {
          cell->get_dof_indices(cell_dofs);
          for (unsigned int i = 0; i < cell_dofs.size(); ++i)
            {
              const auto [component, vertex] = fe.system_to_component_index(i);
              values[cell_dofs[i]] = field(cell->vertex(vertex), component);
              component_of[cell_dofs[i]] = component;
            }
        }
    Forms result;
    penalty.for_each_face(
      dof_handler,
      true,
      [&](const FullMatrix<double>                   &matrix,
          const FullMatrix<double>                   &schur,
          const std::vector<types::global_dof_index> &dofs) {
        ++result.faces;
        for (unsigned int i = 0; i < dofs.size(); ++i)
          for (unsigned int j = 0; j < dofs.size(); ++j)
            {
              const double product    = values.at(dofs[i]) * values.at(dofs[j]);
              const bool   pressure_i = component_of.at(dofs[i]) == dim;
              // The matrix couples each component with itself only.
              if (pressure_i)
                result.pressure += matrix(i, j) * product;
              else
                result.velocity += matrix(i, j) * product;
              result.schur += schur(i, j) * product;
            }
      });
    const MPI_Comm comm = dof_handler.get_communicator();
    result.velocity     = Utilities::MPI::sum(result.velocity, comm);
    result.pressure     = Utilities::MPI::sum(result.pressure, comm);
    result.schur        = Utilities::MPI::sum(result.schur, comm);
    result.faces        = Utilities::MPI::sum(result.faces, comm);
    return result;
  }
} // namespace

int
main(int argc, char **argv)
{
  return unit_test::run(argc, argv, [](std::ostream &out) {
    constexpr int                           dim  = 2;
    const MPI_Comm                          comm = MPI_COMM_WORLD;
    parallel::distributed::Triangulation<2> triangulation(comm);
    GridGenerator::hyper_cube(triangulation, 0, 1);
    triangulation.refine_global(4);
    const double h = 1. / 16;

    vefs::TransportedFields<dim> fields(triangulation, false, false, {});
    fields.setup_dofs();
    for (const auto &node : fields.nodes())
      fields.set_level_set(node, node.point[1] - 0.41);
    fields.finalize();
    const vefs::LiquidDomain<dim> domain(fields);

    unit_test::FlowStepSetup setup;
    setup.cavity.cavity_upper = {1, 1};
    setup.stress.resolve();
    const double                   tau        = 0.01;
    const vefs::FlowStepParameters parameters = setup.step(4, tau);
    const auto                    &material   = setup.material;
    const auto                    &solver     = setup.solver;
    const vefs::Rheology<dim>      rheology(material, setup.stress, 0.);
    vefs::FlowElements<dim>        elements(setup.flow, 4);

    const FESystem<dim> fe(FE_Q<dim>(1), dim, FE_Q<dim>(1), 1);
    DoFHandler<dim>     dof_handler(triangulation);
    dof_handler.distribute_dofs(fe);
    elements.classify(dof_handler, domain);
    vefs::GhostPenalty<dim> penalty(parameters, rheology, fe, elements, tau);

    const double gamma = solver.ghost_penalty;
    const double rho   = material.density;
    const double mu    = rheology.effective_viscosity(tau);
    const double tau_K =
      solver.pressure_stabilization / (rho / tau + 4 * mu / (h * h));
    // 15 vertical faces, each int_F (2h)^2 = 4 h^3.
    const double jumps = 15 * 4 * h * h * h;

    const Forms quadratic_velocity =
      forms<dim>(penalty, dof_handler, [](const Point<dim> &p, unsigned int c) {
        return c == 0 ? p[0] * p[0] : 0.;
      });
    const Forms quadratic_pressure =
      forms<dim>(penalty, dof_handler, [](const Point<dim> &p, unsigned int c) {
        return c == dim ? p[0] * p[0] : 0.;
      });
    const Forms linear =
      forms<dim>(penalty, dof_handler, [](const Point<dim> &p, unsigned int c) {
        return 0.3 + c - (1.2 + c) * p[0] + (0.7 - c) * p[1];
      });

    out << "faces visited: " << quadratic_velocity.faces << '\n';
    const double velocity_form = gamma * (mu + rho * h * h / tau) * h * jumps;
    const double pressure_form = -gamma * tau_K * h * jumps;
    const double schur_form    = gamma * (tau / rho + tau_K) * h * jumps;
    unit_test::check_below(out,
                           "x^2 velocity, velocity form, relative error",
                           std::abs(
                             quadratic_velocity.velocity / velocity_form - 1),
                           1e-10);
    unit_test::check_below(out,
                           "x^2 pressure, pressure form, relative error",
                           std::abs(
                             quadratic_pressure.pressure / pressure_form - 1),
                           1e-10);
    unit_test::check_below(out,
                           "x^2 pressure, Schur form, relative error",
                           std::abs(quadratic_pressure.schur / schur_form - 1),
                           1e-10);
    unit_test::check_below(out,
                           "linear fields, velocity form over the x^2 one",
                           std::abs(linear.velocity / velocity_form),
                           1e-10);
    unit_test::check_below(out,
                           "linear fields, pressure form over the x^2 one",
                           std::abs(linear.pressure / pressure_form),
                           1e-10);
    unit_test::check_below(out,
                           "linear fields, Schur form over the x^2 one",
                           std::abs(linear.schur / schur_form),
                           1e-10);
  });
}
