// StokesCellSystem (stokes_cell_system.h) against the same weak form
// assembled the textbook way, with deal.II's FEValues and extractors on the
// flow's Q1-Q1 element (doc/time_step_flow.md, step 7):
//   a(u, v) = rho/tau (u, v) + 2 mu (eps(u), eps(v))
//             + k_g ((grad u) sigma*, eps(v)) - (p, div v)
//   b(u, q) = -(q, div u) - tau_K rho/tau (u, grad q) - tau_K (grad p, grad q)
//   f(v)    = (rho/tau u* + rho g, v) - k_s (sigma*, grad v)
//   f(q)    = -tau_K (rho/tau u* + rho g + k_s div sigma*, grad q)
// with tau_K = 0.25 / (rho/tau + 4 mu/h^2), and the lumped pressure mass
// (N_i, 1)/mu; mu, k_g (geometric factor) and k_s (explicit stress factor)
// from the rheology. Cells wholly in the liquid of an anisotropic mesh
// (cells 1/4 x 1/16 (x 1/16)), u* and sigma* smooth fields interpolated at
// the vertices, a Newtonian liquid and an Oldroyd-B one (lambda = 0.05 s,
// eta_p = 2 Pa s), tau = 0.01 s. The reference uses a Gauss rule of 3
// points, exact for these polynomial integrands as the code's own rule is:
// the two agree to round-off, relative error below 1e-12 of the largest
// entry. 1 and 2 ranks. Then the lumped mass that 'Solver/Small cut cell
// mass' adds to a cell with a small liquid part (check_small_cut_cell_mass).

#include "flow_step_setup.h"
#include "unit_test.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_generator.h>

#include <vefs/flow/stokes_cell_system.h>

#include <iostream>

using namespace dealii;

namespace
{
  /**
   * The anisotropic test mesh: the box [0, 1] x [0, 0.5] (x [0, 0.5]) of
   * 1 x 2 (x 2) cells refined twice; returns its upper corner.
   */
  template <int dim>
  Point<dim>
  make_mesh(parallel::distributed::Triangulation<dim> &triangulation)
  {
    Point<dim>                upper;
    std::vector<unsigned int> repetitions(dim, 2);
    repetitions[0] = 1;
    for (unsigned int d = 0; d < dim; ++d)
      upper[d] = d == 0 ? 1 : 0.5;
    GridGenerator::subdivided_hyper_rectangle(triangulation,
                                              repetitions,
                                              Point<dim>(),
                                              upper);
    triangulation.refine_global(2);
    return upper;
  }

  template <int dim>
  void
  check(std::ostream &out, const bool oldroyd_b)
  {
    const MPI_Comm                            comm = MPI_COMM_WORLD;
    parallel::distributed::Triangulation<dim> triangulation(comm);
    const Point<dim>                          upper = make_mesh(triangulation);

    unit_test::FlowStepSetup  setup;
    vefs::CavityParameters   &cavity   = setup.cavity;
    vefs::MaterialParameters &material = setup.material;
    cavity.cavity_lower.assign(dim, 0.);
    cavity.cavity_upper.assign(upper.begin_raw(), upper.end_raw());
    material.gravity.assign(dim, 0.);
    material.gravity[dim - 1]  = -9.81;
    material.gravity[0]        = 1.3;
    material.solvent_viscosity = 0.5;
    if (oldroyd_b)
      {
        material.polymer_viscosity = 2;
        material.relaxation_time   = 0.05;
      }
    setup.stress.resolve();
    const double                   tau        = 0.01;
    const vefs::FlowStepParameters parameters = setup.step(2, tau);
    const vefs::Rheology<dim>      rheology(material, setup.stress, 0.);
    const vefs::FlowElements<dim>  elements(setup.flow, 2);

    vefs::TransportedFields<dim> fields(triangulation, oldroyd_b, false, {});
    fields.setup_dofs();
    for (const auto &node : fields.nodes())
      {
        const Point<dim> &p = node.point;
        fields.set_level_set(node, -1);
        Tensor<1, dim> u;
        for (unsigned int d = 0; d < dim; ++d)
          u[d] = std::sin(2 * p[0] + d) * std::cos(3 * p[1] - d);
        fields.set_velocity(node, u);
        if (oldroyd_b)
          {
            SymmetricTensor<2, dim> sigma;
            for (unsigned int a = 0; a < dim; ++a)
              for (unsigned int b = a; b < dim; ++b)
                sigma[a][b] = std::cos(p[0] + 2 * p[1] + a - b) + a * b;
            fields.set_stress(node, sigma);
          }
      }
    fields.finalize();
    const vefs::LiquidDomain<dim> domain(fields);

    const FESystem<dim> fe(FE_Q<dim>(1), dim, FE_Q<dim>(1), 1);
    DoFHandler<dim>     dof_handler(triangulation);
    dof_handler.distribute_dofs(fe);
    vefs::StokesCellSystem<dim>
      system(parameters, rheology, fe, fields, domain, elements, tau);

    const double   rho = material.density;
    const double   mu  = rheology.effective_viscosity(tau);
    const double   k_g = rheology.geometric_factor(tau);
    const double   k_s = rheology.explicit_stress_factor(tau);
    Tensor<1, dim> gravity;
    for (unsigned int d = 0; d < dim; ++d)
      gravity[d] = material.gravity[d];

    const QGauss<dim>                quadrature(3);
    FEValues<dim>                    values(fe,
                         quadrature,
                         update_values | update_gradients | update_JxW_values |
                           update_quadrature_points);
    const FEValuesExtractors::Vector velocity(0);
    const FEValuesExtractors::Scalar pressure(dim);
    const unsigned int               n = fe.n_dofs_per_cell();
    FullMatrix<double>               matrix(n, n);
    Vector<double>                   rhs(n), pressure_mass(n);

    double matrix_error = 0, matrix_size = 0, rhs_error = 0, rhs_size = 0,
           mass_error = 0, mass_size = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        if (!cell->is_locally_owned())
          continue;
        const auto transport_cell = fields.cell_of(cell);
        system.compute(cell);
        values.reinit(cell);
        const double h     = cell->minimum_vertex_distance();
        const double tau_K = 0.25 / (rho / tau + 4 * mu / (h * h));

        // u*, sigma* and div sigma* at the quadrature points, from the
        // vertex values by the Q1 shape functions (those of the pressure).
        std::vector<Tensor<1, dim>>          u_star(quadrature.size());
        std::vector<SymmetricTensor<2, dim>> sigma(quadrature.size());
        std::vector<Tensor<1, dim>>          div_sigma(quadrature.size());
        for (unsigned int i = 0; i < n; ++i)
          if (fe.system_to_component_index(i).first == dim)
            {
              const unsigned int   v = fe.system_to_component_index(i).second;
              const Tensor<1, dim> u = fields.velocity_at(transport_cell, v);
              const SymmetricTensor<2, dim> s =
                oldroyd_b ? fields.stress_at(transport_cell, v)
                          : SymmetricTensor<2, dim>();
              for (const unsigned int q : values.quadrature_point_indices())
                {
                  u_star[q] += values[pressure].value(i, q) * u;
                  sigma[q] += values[pressure].value(i, q) * s;
                  div_sigma[q] += s * values[pressure].gradient(i, q);
                }
            }

        matrix        = 0;
        rhs           = 0;
        pressure_mass = 0;
        for (const unsigned int q : values.quadrature_point_indices())
          {
            const double         JxW = values.JxW(q);
            const Tensor<1, dim> forcing =
              rho / tau * u_star[q] + rho * gravity;
            for (unsigned int i = 0; i < n; ++i)
              {
                const Tensor<1, dim> v      = values[velocity].value(i, q);
                const Tensor<2, dim> grad_v = values[velocity].gradient(i, q);
                const SymmetricTensor<2, dim> eps_v =
                  values[velocity].symmetric_gradient(i, q);
                const double         div_v  = values[velocity].divergence(i, q);
                const double         q_i    = values[pressure].value(i, q);
                const Tensor<1, dim> grad_q = values[pressure].gradient(i, q);
                for (unsigned int j = 0; j < n; ++j)
                  {
                    const Tensor<1, dim> u = values[velocity].value(j, q);
                    const Tensor<2, dim> grad_u =
                      values[velocity].gradient(j, q);
                    const double div_u = values[velocity].divergence(j, q);
                    const double p     = values[pressure].value(j, q);
                    const Tensor<1, dim> grad_p =
                      values[pressure].gradient(j, q);
                    double a =
                      rho / tau * (u * v) +
                      2 * mu *
                        scalar_product(values[velocity].symmetric_gradient(j,
                                                                           q),
                                       eps_v) -
                      p * div_v - q_i * div_u -
                      tau_K * rho / tau * (u * grad_q) -
                      tau_K * (grad_p * grad_q);
                    if (oldroyd_b)
                      a +=
                        k_g * scalar_product(grad_u * Tensor<2, dim>(sigma[q]),
                                             eps_v);
                    matrix(i, j) += a * JxW;
                  }
                rhs(i) += (forcing * v -
                           tau_K * ((forcing + k_s * div_sigma[q]) * grad_q)) *
                          JxW;
                if (oldroyd_b)
                  rhs(i) -= k_s *
                            scalar_product(Tensor<2, dim>(sigma[q]), grad_v) *
                            JxW;
                pressure_mass(i) += q_i * JxW / mu;
              }
          }
        for (unsigned int i = 0; i < n; ++i)
          {
            for (unsigned int j = 0; j < n; ++j)
              {
                matrix_error =
                  std::max(matrix_error,
                           std::abs(system.matrix(i, j) - matrix(i, j)));
                matrix_size = std::max(matrix_size, std::abs(matrix(i, j)));
              }
            rhs_error = std::max(rhs_error, std::abs(system.rhs(i) - rhs(i)));
            rhs_size  = std::max(rhs_size, std::abs(rhs(i)));
            mass_error =
              std::max(mass_error,
                       std::abs(system.pressure_mass(i) - pressure_mass(i)));
            mass_size = std::max(mass_size, std::abs(pressure_mass(i)));
          }
      }
    const std::string label = std::to_string(dim) + "D, " +
                              (oldroyd_b ? "Oldroyd-B" : "Newtonian") + ", ";
    unit_test::check_below(out,
                           label + "matrix, relative error",
                           Utilities::MPI::max(matrix_error, comm) /
                             Utilities::MPI::max(matrix_size, comm),
                           1e-12);
    unit_test::check_below(out,
                           label + "right-hand side, relative error",
                           Utilities::MPI::max(rhs_error, comm) /
                             Utilities::MPI::max(rhs_size, comm),
                           1e-12);
    unit_test::check_below(out,
                           label + "pressure mass, relative error",
                           Utilities::MPI::max(mass_error, comm) /
                             Utilities::MPI::max(mass_size, comm),
                           1e-12);
  }

  // 'Solver/Small cut cell mass' m: the level set x - 0.251 cuts the cells
  // of the column 0.25 < x < 0.5 (width 0.25) with the liquid fraction
  // f = 0.004. Against the same cell without it (m = 0), each velocity row
  // of such a cell must gain (m - f) rho/tau |K| / 2^dim on its diagonal
  // and that mass times u* at its vertex on the right-hand side, nothing
  // else.
  template <int dim>
  void
  check_small_cut_cell_mass(std::ostream &out)
  {
    const MPI_Comm                            comm = MPI_COMM_WORLD;
    parallel::distributed::Triangulation<dim> triangulation(comm);
    const Point<dim>                          upper = make_mesh(triangulation);

    unit_test::FlowStepSetup setup;
    setup.cavity.cavity_lower.assign(dim, 0.);
    setup.cavity.cavity_upper.assign(upper.begin_raw(), upper.end_raw());
    setup.material.gravity.assign(dim, 0.);
    setup.material.gravity[dim - 1]  = -9.81;
    setup.material.solvent_viscosity = 0.5;
    setup.stress.resolve();
    const double                   tau        = 0.01;
    const vefs::FlowStepParameters parameters = setup.step(2, tau);
    const vefs::Rheology<dim>      rheology(setup.material, setup.stress, 0.);
    const vefs::FlowElements<dim>  elements(setup.flow, 2);

    vefs::TransportedFields<dim> fields(triangulation, false, false, {});
    fields.setup_dofs();
    for (const auto &node : fields.nodes())
      {
        const Point<dim> &p = node.point;
        fields.set_level_set(node, p[0] - 0.251);
        Tensor<1, dim> u;
        for (unsigned int d = 0; d < dim; ++d)
          u[d] = std::sin(2 * p[0] + d) * std::cos(3 * p[1] - d);
        fields.set_velocity(node, u);
      }
    fields.finalize();
    const vefs::LiquidDomain<dim> domain(fields);

    const FESystem<dim> fe(FE_Q<dim>(1), dim, FE_Q<dim>(1), 1);
    DoFHandler<dim>     dof_handler(triangulation);
    dof_handler.distribute_dofs(fe);
    const double small_mass          = 0.01;
    setup.solver.small_cut_cell_mass = small_mass;
    vefs::StokesCellSystem<dim> with_mass =
      {parameters, rheology, fe, fields, domain, elements, tau};
    vefs::StokesCellSystem<dim> without =
      {parameters, rheology, fe, fields, domain, elements, tau};
    const double mass_factor =
      setup.material.density / parameters.mass_step(tau);

    double             error = 0, size = 0, fraction = 0;
    const unsigned int n = fe.n_dofs_per_cell();
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        if (!cell->is_locally_owned() ||
            domain.location(cell) != vefs::LiquidDomain<dim>::Location::cut)
          continue;
        setup.solver.small_cut_cell_mass = small_mass;
        with_mass.compute(cell);
        setup.solver.small_cut_cell_mass = 0;
        without.compute(cell);
        fraction          = domain.fractions()[cell->active_cell_index()];
        const double mass = (small_mass - fraction) * mass_factor *
                            cell->measure() /
                            GeometryInfo<dim>::vertices_per_cell;
        const auto transport_cell = fields.cell_of(cell);
        for (unsigned int i = 0; i < n; ++i)
          {
            const auto [component, vertex] = fe.system_to_component_index(i);
            const bool velocity            = component < dim;
            for (unsigned int j = 0; j < n; ++j)
              {
                const double expected = velocity && i == j ? mass : 0.;
                error                 = std::max(error,
                                 std::abs(with_mass.matrix(i, j) -
                                          without.matrix(i, j) - expected));
                size = std::max(size, std::abs(with_mass.matrix(i, j)));
              }
            const double expected =
              velocity
                ? mass * fields.velocity_at(transport_cell, vertex)[component]
                : 0.;
            error =
              std::max(error,
                       std::abs(with_mass.rhs(i) - without.rhs(i) - expected));
          }
      }
    out << dim << "D, liquid fraction of the cut cells: "
        << Utilities::MPI::max(fraction, comm) << '\n';
    unit_test::check_below(out,
                           std::to_string(dim) +
                             "D, small cut cell mass, relative error",
                           Utilities::MPI::max(error, comm) /
                             Utilities::MPI::max(size, comm),
                           1e-12);
  }
} // namespace

int
main(int argc, char **argv)
{
  return unit_test::run(argc, argv, [](std::ostream &out) {
    check<2>(out, false);
    check<2>(out, true);
    check<3>(out, false);
    check<3>(out, true);
    check_small_cut_cell_mass<2>(out);
    check_small_cut_cell_mass<3>(out);
  });
}
