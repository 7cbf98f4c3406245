// The stress update of design section 2, step 4, against exact answers of
// the discrete scheme:
// - Rheology::updated_stress() of an elastic solid (alpha = 0, k = 1):
//   the exponential update in a homogeneous simple shear (exp(tau L) =
//   I + tau L) gives after n steps sigma = G (F F^T - I) with F = I +
//   gamma e_x e_y^T, gamma = n tau gdot, exactly; in planar extension
//   F = diag(e^(n tau e), e^(-n tau e)). The linear update in simple shear
//   gives sigma_xy = G gamma, sigma_xx = G gamma^2 (1 - 1/n), sigma_yy = 0
//   (by induction: sigma_xy grows by tau G gdot a step, sigma_xx by
//   2 tau gdot sigma_xy).
// - Oldroyd-B (alpha = 1) at rest: both updates multiply sigma by
//   k = lambda / (lambda + tau) per step.
// - update_stress() on a mesh with hanging nodes cut by a plane, in the
//   same simple shear: every node of a liquid cell gets sigma of one step
//   of the exponential update from the advected sigma*, the others keep
//   sigma*; elastic_energy_of_pointwise_update() gives the liquid's
//   strain energy of that sigma, G/2 (tr B - 2 - ln det B) times its area,
//   and so does the nodal update (its own share of the energy budget is
//   zero in a homogeneous flow). The same with the nodal stress of the
//   lumped increment (the update's increment at the liquid's quadrature
//   points, lumped onto the nodes), which is exact there as well. 1 and 2
//   ranks.
// Tolerance: relative error below 1e-12 (round-off of a few tens of
// operations per step).

#include "unit_test.h"

#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/grid/grid_generator.h>

#include <vefs/stress/rheology.h>
#include <vefs/stress/stress.h>
#include <vefs/transport/liquid_domain.h>

#include <iostream>

using namespace dealii;

namespace
{
  /** Relaxation time of the materials below. */
  constexpr double relaxation_time = 0.5;

  /** G = 4 Pa; alpha = 1: Oldroyd-B, 0: elastic solid. */
  vefs::Rheology<2>
  material(const double alpha, const vefs::StressUpdate update)
  {
    vefs::MaterialParameters material;
    material.polymer_viscosity = 2;
    material.relaxation_time   = relaxation_time;
    material.alpha             = alpha;
    vefs::StressParameters stress;
    stress.stress_update = update;
    stress.stress_theta  = 1;
    return vefs::Rheology<2>(material, stress, 0);
  }

  double
  relative_error(const SymmetricTensor<2, 2> &computed,
                 const SymmetricTensor<2, 2> &exact)
  {
    return (computed - exact).norm() / exact.norm();
  }

  /** G (F F^T - I). */
  SymmetricTensor<2, 2>
  elastic_stress(const double G, const Tensor<2, 2> &F)
  {
    return G * (symmetrize(F * transpose(F)) - unit_symmetric_tensor<2>());
  }

  void
  check_updates(std::ostream &out)
  {
    const double       tau = 0.01, rate = 3;
    const unsigned int n     = 50;
    const double       gamma = n * tau * rate;
    Tensor<2, 2>       shear;
    shear[0][1] = rate;

    {
      const vefs::Rheology<2> elastic(
        material(0, vefs::StressUpdate::exponential));
      const double          G = elastic.shear_modulus();
      SymmetricTensor<2, 2> sigma;
      for (unsigned int i = 0; i < n; ++i)
        sigma = elastic.updated_stress(sigma, shear, tau);
      Tensor<2, 2> F = unit_symmetric_tensor<2>();
      F[0][1]        = gamma;
      unit_test::check_below(out,
                             "exponential, simple shear, G (F F^T - I)",
                             relative_error(sigma, elastic_stress(G, F)),
                             1e-12);

      Tensor<2, 2> extension;
      extension[0][0] = 2;
      extension[1][1] = -2;
      sigma           = SymmetricTensor<2, 2>();
      for (unsigned int i = 0; i < n; ++i)
        sigma = elastic.updated_stress(sigma, extension, tau);
      F       = Tensor<2, 2>();
      F[0][0] = std::exp(2. * n * tau);
      F[1][1] = std::exp(-2. * n * tau);
      unit_test::check_below(out,
                             "exponential, planar extension, G (F F^T - I)",
                             relative_error(sigma, elastic_stress(G, F)),
                             1e-12);
    }

    {
      const vefs::Rheology<2> elastic(material(0, vefs::StressUpdate::linear));
      const double            G = elastic.shear_modulus();
      SymmetricTensor<2, 2>   sigma, exact;
      for (unsigned int i = 0; i < n; ++i)
        sigma = elastic.updated_stress(sigma, shear, tau);
      exact[0][0] = G * gamma * gamma * (1 - 1. / n);
      exact[0][1] = G * gamma;
      unit_test::check_below(out,
                             "linear, simple shear, discrete exact",
                             relative_error(sigma, exact),
                             1e-12);
    }

    for (const auto update :
         {vefs::StressUpdate::linear, vefs::StressUpdate::exponential})
      {
        const vefs::Rheology<2> liquid = material(1, update);
        SymmetricTensor<2, 2>   initial, sigma;
        initial[0][0] = 3;
        initial[0][1] = -1;
        initial[1][1] = 0.5;
        sigma         = initial;
        for (unsigned int i = 0; i < n; ++i)
          sigma = liquid.updated_stress(sigma, Tensor<2, 2>(), tau);
        const double lambda = relaxation_time;
        unit_test::check_below(
          out,
          std::string("Oldroyd-B at rest, ") +
            (update == vefs::StressUpdate::linear ? "linear" : "exponential") +
            ", (lambda / (lambda + tau))^n sigma_0",
          relative_error(sigma, std::pow(lambda / (lambda + tau), n) * initial),
          1e-12);
      }
  }

  void
  check_field_update(std::ostream           &out,
                     const vefs::NodalStress nodal_stress,
                     const std::string      &label)
  {
    const double                            tau = 0.02, rate = 3;
    parallel::distributed::Triangulation<2> triangulation(MPI_COMM_WORLD);
    GridGenerator::hyper_cube(triangulation, 0, 1, true);
    triangulation.refine_global(3);
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned() && cell->center()[1] < 0.4)
        cell->set_refine_flag();
    triangulation.execute_coarsening_and_refinement();

    vefs::TransportedFields<2> fields(triangulation, true, false, {});
    fields.setup_dofs();
    SymmetricTensor<2, 2> advected;
    advected[0][0] = 0.7;
    advected[0][1] = -0.4;
    advected[1][1] = 1.1;
    Vector<double> stress_values(3);
    for (unsigned int i = 0; i < 3; ++i)
      stress_values[i] = advected.access_raw_entry(i);
    // The plane x = 0.53 crosses a column of cells.
    fields.interpolate(
      ScalarFunctionFromFunctionObject<2>(
        [](const Point<2> &p) { return p[0] - 0.53; }),
      unit_test::SimpleShear(rate),
      std::make_unique<Functions::ConstantFunction<2>>(stress_values).get());

    const vefs::LiquidDomain<2> domain(fields);
    const vefs::Rheology<2>     elastic(
      material(0, vefs::StressUpdate::exponential));
    const double pointwise_energy =
      vefs::elastic_energy_of_pointwise_update(fields,
                                               fields.vector(),
                                               domain,
                                               elastic,
                                               tau);
    const auto report = vefs::update_stress(fields,
                                            fields.vector(),
                                            domain,
                                            elastic,
                                            tau,
                                            true,
                                            nodal_stress);

    // The nodes of liquid cells, owned or ghost.
    std::set<types::global_dof_index> liquid_nodes;
    for (const auto &cell : fields.dof_handler.active_cell_iterators())
      if (!cell->is_artificial() && domain.has_liquid(cell))
        for (const unsigned int v : cell->vertex_indices())
          liquid_nodes.insert(cell->vertex_dof_index(v, 0));

    Tensor<2, 2> F                = unit_symmetric_tensor<2>();
    F[0][1]                       = tau * rate;
    const double                G = elastic.shear_modulus();
    const SymmetricTensor<2, 2> B_advected =
      unit_symmetric_tensor<2>() + advected / G;
    const SymmetricTensor<2, 2> updated =
      G * (symmetrize(F * Tensor<2, 2>(B_advected) * transpose(F)) -
           unit_symmetric_tensor<2>());

    double       error_liquid = 0, error_other = 0;
    unsigned int n_liquid = 0, n_other = 0;
    for (const auto &node : fields.nodes())
      {
        SymmetricTensor<2, 2> sigma;
        for (unsigned int i = 0; i < 3; ++i)
          sigma.access_raw_entry(i) = fields.vector()(
            node.dofs[vefs::TransportedFields<2>::first_stress_component + i]);
        if (liquid_nodes.count(node.dofs[0]))
          {
            error_liquid =
              std::max(error_liquid, relative_error(sigma, updated));
            ++n_liquid;
          }
        else
          {
            error_other = std::max(error_other, (sigma - advected).norm());
            ++n_other;
          }
      }
    const MPI_Comm comm = MPI_COMM_WORLD;
    unit_test::check_below(out,
                           label + "update_stress, nodes of liquid cells",
                           Utilities::MPI::max(error_liquid, comm),
                           1e-12);
    unit_test::check_zero(out,
                          label +
                            "update_stress, other nodes, |sigma - sigma*|",
                          Utilities::MPI::max(error_other, comm));
    out << label
        << "nodes of liquid cells: " << Utilities::MPI::sum(n_liquid, comm)
        << ", other nodes: " << Utilities::MPI::sum(n_other, comm) << '\n';
    unit_test::check_below(out,
                           label + "largest velocity gradient - gdot",
                           std::abs(report.max_velocity_gradient - rate),
                           1e-12);

    // The energy budget's reference: in a homogeneous shear the update at
    // the quadrature points is the nodal one, and the liquid (x < 0.53,
    // height 1) holds G/2 (tr B - 2 - ln det B) of the updated B.
    const SymmetricTensor<2, 2> B_updated =
      unit_symmetric_tensor<2>() + updated / G;
    const double exact_energy =
      0.53 * 0.5 * G *
      (trace(B_updated) - 2 - std::log(determinant(B_updated)));
    unit_test::check_below(
      out,
      label + "elastic energy of the pointwise update, relative error",
      std::abs(pointwise_energy - exact_energy) / exact_energy,
      1e-12);
    const double nodal_energy =
      vefs::measure_stress(fields, domain, elastic).elastic_energy;
    unit_test::check_below(out,
                           label + "the nodal update's own share, relative",
                           std::abs(nodal_energy - pointwise_energy) /
                             exact_energy,
                           1e-12);
  }
} // namespace

int
main(int argc, char **argv)
{
  return unit_test::run(argc, argv, [](std::ostream &out) {
    check_updates(out);
    check_field_update(out, vefs::NodalStress::vertex_average, "");
    check_field_update(out,
                       vefs::NodalStress::lumped_increment,
                       "lumped increment: ");
  });
}
