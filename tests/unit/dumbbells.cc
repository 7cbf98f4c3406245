// The dumbbells' pieces (doc/dumbbells.md) against exact answers:
// - equilibrium_sample(): the second moment of the N_f vectors is the
//   identity (N_f = 2, 7, 1000), by construction up to round-off.
// - orthogonal_factor(): of A = R U (R a rotation, U symmetric positive
//   definite) it is R.
// - moment_map(): if B_new = F B F^T it is F; for any B_new, T B T^T =
//   B_new (2D and 3D).
// - increments(): a function of (seed, step) only; over 200,000 draws the
//   mean is within 5 standard errors (5 / sqrt(n)) of 0 and the variance
//   within 5 standard errors (5 sqrt(2 / n)) of 1.
// - update_dumbbells() on a mesh with hanging nodes cut by a plane, in a
//   simple shear (every cell sees the same exp(tau L) = F), alpha = 0: the
//   fields at the nodes of liquid cells become F q*, exactly, and the
//   ensemble stress equals update_stress() of the same advected stress;
//   other nodes keep q*. 1 and 2 ranks.
// - Variance reduction: a liquid at rest (alpha = 1, no velocity, no
//   initial stress), 20 steps: the fields take the same increments as
//   their equilibrium fields and stay equal to them, so the variance-
//   reduced ensemble stress is zero up to round-off, where the plain
//   estimator G (<q q^T> - I) has the noise of N_f = 50 fields (above
//   0.01 G); the equilibrium fields follow p_i = sqrt(k) p_i + sqrt(1 - k)
//   xi_i exactly. 1 and 2 ranks.
// - match_dumbbells_to_stress(): fields drawn for a stress sigma_0, then a
//   stress sigma(x) that differs from node to node (as an interpolation
//   leaves it): afterwards <q q^T> = c(sigma(x)) + <p p^T> - I at every
//   node and the stress is still sigma(x), with and without variance
//   reduction; called again, it leaves the fields as they are (the map
//   nearest to the identity is the identity); a node whose sigma has a
//   conformation that is not positive definite keeps its fields and takes
//   their ensemble stress. 1 and 2 ranks.
// Tolerance: relative error below 1e-12 (round-off of a few tens of
// operations), unless stated.

#include "unit_test.h"

#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/grid/grid_generator.h>

#include <vefs/stress/dumbbells.h>
#include <vefs/stress/rheology.h>
#include <vefs/stress/stress.h>
#include <vefs/transport/liquid_domain.h>

#include <cmath>
#include <iostream>
#include <set>

using namespace dealii;
namespace db = vefs::dumbbells;

namespace
{
  template <int dim>
  SymmetricTensor<2, dim>
  some_positive_definite()
  {
    SymmetricTensor<2, dim> B = unit_symmetric_tensor<dim>();
    B[0][0]                   = 1.7;
    B[0][1]                   = -0.4;
    B[dim - 1][dim - 1]       = 0.6;
    if (dim == 3)
      B[1][2] = 0.3;
    return B;
  }

  template <int dim>
  Tensor<2, dim>
  some_deformation()
  {
    Tensor<2, dim> F;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        F[i][j] =
          (i == j ? 1.1 + 0.2 * i : 0.) + 0.3 * std::sin(1. + i + 2 * j);
    return F;
  }

  template <int dim>
  void
  check_point_pieces(std::ostream &out)
  {
    const std::string name = std::to_string(dim) + "D, ";
    for (const unsigned int n : {2u, 7u, 1000u})
      if (n >= dim)
        unit_test::check_below(
          out,
          name + "N_f = " + std::to_string(n) + ", |<q q^T> - I|",
          (db::second_moment(db::equilibrium_sample<dim>(n, 5)) -
           unit_symmetric_tensor<dim>())
            .norm(),
          1e-12);

    // A rotation by 0.7 about the last axis times a symmetric positive
    // definite U.
    Tensor<2, dim> R = unit_symmetric_tensor<dim>();
    R[0][0] = R[1][1] = std::cos(0.7);
    R[0][1]           = -std::sin(0.7);
    R[1][0]           = std::sin(0.7);
    const Tensor<2, dim> U(some_positive_definite<dim>());
    unit_test::check_below(out,
                           name + "orthogonal factor of R U, |. - R|",
                           (db::orthogonal_factor(R * U) - R).norm(),
                           1e-12);

    const SymmetricTensor<2, dim> B = some_positive_definite<dim>();
    const Tensor<2, dim>          F = some_deformation<dim>();
    const SymmetricTensor<2, dim> FBFt =
      symmetrize(F * Tensor<2, dim>(B) * transpose(F));
    unit_test::check_below(out,
                           name + "moment map to F B F^T, |T - F| / |F|",
                           (db::moment_map(B, FBFt, F) - F).norm() / F.norm(),
                           1e-12);
    // Another target: the map keeps the second moment exact.
    const SymmetricTensor<2, dim> target =
      0.5 * FBFt + 0.5 * unit_symmetric_tensor<dim>();
    const Tensor<2, dim> T = db::moment_map(B, target, F);
    unit_test::check_below(
      out,
      name + "moment map to another B_new, |T B T^T - B_new| / |B_new|",
      (symmetrize(T * Tensor<2, dim>(B) * transpose(T)) - target).norm() /
        target.norm(),
      1e-12);
  }

  void
  check_increments(std::ostream &out)
  {
    const auto a    = db::increments<2>(50, 3, 17);
    const auto b    = db::increments<2>(50, 3, 17);
    const auto c    = db::increments<2>(50, 3, 18);
    double     same = 0, other = 0;
    for (unsigned int i = 0; i < a.size(); ++i)
      {
        same += (a[i] - b[i]).norm();
        other += (a[i] - c[i]).norm();
      }
    unit_test::check_zero(out,
                          "increments of one (seed, step) differ by",
                          same);
    out << "increments of the next step differ: " << (other > 0 ? "yes" : "NO")
        << '\n';

    const unsigned int n     = 100000;
    const auto         draws = db::increments<2>(n, 11, 1);
    double             sum = 0, squares = 0;
    for (const auto &xi : draws)
      for (unsigned int d = 0; d < 2; ++d)
        {
          sum += xi[d];
          squares += xi[d] * xi[d];
        }
    const double n_draws = 2. * n;
    unit_test::check_below(out,
                           "200,000 increments, |mean|",
                           std::abs(sum / n_draws),
                           5 / std::sqrt(n_draws));
    unit_test::check_below(out,
                           "200,000 increments, |variance - 1|",
                           std::abs(squares / n_draws - 1),
                           5 * std::sqrt(2 / n_draws));
  }

  void
  check_field_update(std::ostream &out)
  {
    const double                            tau = 0.02, rate = 3;
    const unsigned int                      n_fields = 5;
    parallel::distributed::Triangulation<2> triangulation(MPI_COMM_WORLD);
    GridGenerator::hyper_cube(triangulation, 0, 1, true);
    triangulation.refine_global(3);
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned() && cell->center()[1] < 0.4)
        cell->set_refine_flag();
    triangulation.execute_coarsening_and_refinement();

    vefs::MaterialParameters material;
    material.polymer_viscosity = 2;
    material.relaxation_time   = 0.5;
    material.alpha             = 0;
    material.stress_model      = vefs::StressModel::dumbbells;
    vefs::StressParameters stress;
    stress.stress_update = vefs::StressUpdate::exponential;
    const vefs::Rheology<2> elastic(material, stress, 0);

    // Two copies: dumbbells, and the macroscopic stress.
    vefs::TransportedFields<2> fields(triangulation, true, false, {}, n_fields);
    vefs::TransportedFields<2> macroscopic(triangulation, true, false, {});
    SymmetricTensor<2, 2>      advected;
    advected[0][0] = 0.7;
    advected[0][1] = -0.4;
    advected[1][1] = 1.1;
    Vector<double> stress_values(3);
    for (unsigned int i = 0; i < 3; ++i)
      stress_values[i] = advected.access_raw_entry(i);
    const Functions::ConstantFunction<2> initial_stress(stress_values);
    // The plane x = 0.53 crosses a column of cells.
    const ScalarFunctionFromFunctionObject<2> level_set(
      [](const Point<2> &p) { return p[0] - 0.53; });
    for (auto *f : {&fields, &macroscopic})
      {
        f->setup_dofs();
        f->interpolate(level_set,
                       unit_test::SimpleShear(rate),
                       &initial_stress);
      }
    vefs::set_initial_dumbbells(fields, elastic, 4, false);
    std::vector<std::vector<Tensor<1, 2>>> q_star;
    for (const auto &node : fields.nodes())
      {
        q_star.emplace_back();
        for (unsigned int i = 0; i < n_fields; ++i)
          q_star.back().push_back(fields.dumbbell(node, i));
      }

    const vefs::LiquidDomain<2> domain(fields);
    vefs::update_dumbbells(fields,
                           fields.vector(),
                           domain,
                           elastic,
                           tau,
                           db::increments<2>(n_fields, 4, 1));
    const vefs::LiquidDomain<2> macroscopic_domain(macroscopic);
    vefs::update_stress(macroscopic,
                        macroscopic.vector(),
                        macroscopic_domain,
                        elastic,
                        tau,
                        true,
                        vefs::NodalStress::vertex_average);

    std::set<types::global_dof_index> liquid_nodes;
    for (const auto &cell : fields.dof_handler.active_cell_iterators())
      if (!cell->is_artificial() && domain.has_liquid(cell))
        for (const unsigned int v : cell->vertex_indices())
          liquid_nodes.insert(cell->vertex_dof_index(v, 0));

    Tensor<2, 2> F           = unit_symmetric_tensor<2>();
    F[0][1]                  = tau * rate;
    double       field_error = 0, other_error = 0, stress_error = 0;
    unsigned int n_liquid = 0;
    for (unsigned int k = 0; k < fields.nodes().size(); ++k)
      {
        const auto &node   = fields.nodes()[k];
        const bool  liquid = liquid_nodes.count(node.dofs[0]) > 0;
        n_liquid += liquid;
        for (unsigned int i = 0; i < n_fields; ++i)
          {
            const Tensor<1, 2> q = fields.dumbbell(node, i);
            if (liquid)
              field_error =
                std::max(field_error, (q - F * q_star[k][i]).norm() / q.norm());
            else
              other_error = std::max(other_error, (q - q_star[k][i]).norm());
          }
        const SymmetricTensor<2, 2> expected =
          macroscopic.stress(macroscopic.nodes()[k]);
        stress_error =
          std::max(stress_error,
                   (fields.stress(node) - expected).norm() / expected.norm());
      }
    const MPI_Comm comm = MPI_COMM_WORLD;
    unit_test::check_below(
      out,
      "update_dumbbells, nodes of liquid cells, |q - F q*|",
      Utilities::MPI::max(field_error, comm),
      1e-12);
    unit_test::check_zero(out,
                          "update_dumbbells, other nodes, |q - q*|",
                          Utilities::MPI::max(other_error, comm));
    unit_test::check_below(
      out,
      "update_dumbbells, ensemble stress - update_stress(), relative",
      Utilities::MPI::max(stress_error, comm),
      1e-12);
    out << "nodes of liquid cells: " << Utilities::MPI::sum(n_liquid, comm)
        << '\n';
  }

  /** The unit square, 8 x 8 cells, boundary ids by side. */
  void
  uniform_unit_square(parallel::distributed::Triangulation<2> &triangulation)
  {
    GridGenerator::hyper_cube(triangulation, 0, 1, true);
    triangulation.refine_global(3);
  }

  /** An Oldroyd-B liquid (alpha = 1) carried by dumbbells, G = 4. */
  vefs::Rheology<2>
  dumbbell_liquid()
  {
    vefs::MaterialParameters material;
    material.polymer_viscosity = 2;
    material.relaxation_time   = 0.5;
    material.alpha             = 1;
    material.stress_model      = vefs::StressModel::dumbbells;
    vefs::StressParameters stress;
    stress.stress_update = vefs::StressUpdate::exponential;
    return vefs::Rheology<2>(material, stress, 0);
  }

  void
  check_variance_reduction(std::ostream &out)
  {
    const double                            tau      = 0.02;
    const unsigned int                      n_fields = 50, seed = 3;
    parallel::distributed::Triangulation<2> triangulation(MPI_COMM_WORLD);
    uniform_unit_square(triangulation);
    const vefs::Rheology<2> liquid = dumbbell_liquid();
    const double            G      = liquid.shear_modulus();
    const double            k      = liquid.stress_factor(tau);

    const ScalarFunctionFromFunctionObject<2> everywhere_liquid(
      [](const Point<2> &) { return -1.; });
    const Functions::ZeroFunction<2> at_rest(2);
    std::vector<double>              largest_stress;
    std::vector<Tensor<1, 2>>        expected_controls;
    double                           control_error = 0;
    for (const bool reduced : {true, false})
      {
        vefs::TransportedFields<2> fields(triangulation,
                                          true,
                                          false,
                                          {},
                                          n_fields);
        fields.setup_dofs();
        fields.interpolate(everywhere_liquid, at_rest);
        vefs::set_initial_dumbbells(fields, liquid, seed, reduced);
        if (reduced)
          expected_controls = db::equilibrium_sample<2>(n_fields, seed);
        const vefs::LiquidDomain<2> domain(fields);
        for (unsigned int step = 1; step <= 20; ++step)
          {
            const auto xi = db::increments<2>(n_fields, seed, step);
            vefs::update_dumbbells(fields,
                                   fields.vector(),
                                   domain,
                                   liquid,
                                   tau,
                                   xi);
            if (reduced)
              for (unsigned int i = 0; i < n_fields; ++i)
                expected_controls[i] = std::sqrt(k) * expected_controls[i] +
                                       std::sqrt(1 - k) * xi[i];
          }
        if (reduced)
          for (unsigned int i = 0; i < n_fields; ++i)
            control_error = std::max(
              control_error,
              (fields.dumbbell_controls[i] - expected_controls[i]).norm());
        double largest = 0;
        for (const auto &node : fields.nodes())
          largest = std::max(largest, fields.stress(node).norm() / G);
        largest_stress.push_back(Utilities::MPI::max(largest, MPI_COMM_WORLD));
      }
    unit_test::check_below(out,
                           "at rest, variance reduced, max |sigma| / G",
                           largest_stress[0],
                           1e-12);
    out << "at rest, plain estimator, max |sigma| / G above 0.01: "
        << (largest_stress[1] > 0.01 ? "yes" : "NO") << '\n';
    unit_test::check_below(out,
                           "at rest, equilibrium fields, |p - expected|",
                           control_error,
                           1e-12);
  }
  void
  check_match_to_stress(std::ostream &out)
  {
    const unsigned int                      n_fields = 20, seed = 7;
    parallel::distributed::Triangulation<2> triangulation(MPI_COMM_WORLD);
    uniform_unit_square(triangulation);
    const vefs::Rheology<2> liquid = dumbbell_liquid();
    const double            G      = liquid.shear_modulus();

    SymmetricTensor<2, 2> sigma_0;
    sigma_0[0][0] = 0.7 * G;
    sigma_0[0][1] = -0.4 * G;
    sigma_0[1][1] = 0.2 * G;
    Vector<double> stress_values(3);
    for (unsigned int i = 0; i < 3; ++i)
      stress_values[i] = sigma_0.access_raw_entry(i);
    const Functions::ConstantFunction<2>      initial_stress(stress_values);
    const ScalarFunctionFromFunctionObject<2> everywhere_liquid(
      [](const Point<2> &) { return -1.; });
    // What an interpolation might leave: sigma_0 scaled and sheared by
    // position; at x = y = 1 a conformation that is not positive definite.
    const auto interpolated = [&](const Point<2> &p) {
      if (p.distance(Point<2>(1, 1)) < 1e-12)
        return SymmetricTensor<2, 2>(-2 * G * unit_symmetric_tensor<2>());
      SymmetricTensor<2, 2> sigma = (1 + 0.5 * std::sin(3 * p[0])) * sigma_0;
      sigma[0][1] += 0.3 * G * p[1];
      return sigma;
    };

    for (const bool reduced : {false, true})
      {
        const std::string name =
          reduced ? "variance reduced, " : "plain estimator, ";
        vefs::TransportedFields<2> fields(triangulation,
                                          true,
                                          false,
                                          {},
                                          n_fields);
        fields.setup_dofs();
        fields.interpolate(everywhere_liquid,
                           Functions::ZeroFunction<2>(2),
                           &initial_stress);
        vefs::set_initial_dumbbells(fields, liquid, seed, reduced);
        for (const auto &node : fields.nodes())
          fields.set_stress(node, interpolated(node.point));
        fields.finalize();

        vefs::match_dumbbells_to_stress(fields, liquid);
        const SymmetricTensor<2, 2> offset =
          vefs::control_moment(fields) - unit_symmetric_tensor<2>();
        double moment_error = 0, stress_error = 0, kept_error = 0;
        std::vector<std::vector<Tensor<1, 2>>> matched;
        for (const auto &node : fields.nodes())
          {
            matched.emplace_back();
            std::vector<Tensor<1, 2>> q(n_fields);
            for (unsigned int i = 0; i < n_fields; ++i)
              matched.back().push_back(q[i] = fields.dumbbell(node, i));
            const SymmetricTensor<2, 2> sigma = interpolated(node.point);
            if (node.point.distance(Point<2>(1, 1)) < 1e-12)
              kept_error = std::max(kept_error,
                                    (fields.stress(node) -
                                     G * (db::second_moment(q) -
                                          vefs::control_moment(fields)))
                                      .norm());
            else
              {
                const SymmetricTensor<2, 2> target =
                  liquid.conformation(sigma) + offset;
                moment_error = std::max(moment_error,
                                        (db::second_moment(q) - target).norm() /
                                          target.norm());
                stress_error =
                  std::max(stress_error,
                           (fields.stress(node) - sigma).norm() / sigma.norm());
              }
          }
        const MPI_Comm comm = MPI_COMM_WORLD;
        unit_test::check_below(out,
                               name +
                                 "matched, |<q q^T> - c - <p p^T> + I| / |.|",
                               Utilities::MPI::max(moment_error, comm),
                               1e-12);
        unit_test::check_below(out,
                               name + "matched, |stress - sigma| / |sigma|",
                               Utilities::MPI::max(stress_error, comm),
                               1e-12);
        unit_test::check_below(
          out,
          name + "not positive definite, |stress - G (<q q^T> - <p p^T>)| / G",
          Utilities::MPI::max(kept_error, comm) / G,
          1e-12);

        vefs::match_dumbbells_to_stress(fields, liquid);
        double change = 0;
        for (unsigned int k = 0; k < fields.nodes().size(); ++k)
          for (unsigned int i = 0; i < n_fields; ++i)
            change = std::max(
              change,
              (fields.dumbbell(fields.nodes()[k], i) - matched[k][i]).norm() /
                matched[k][i].norm());
        unit_test::check_below(out,
                               name + "matched again, |q - q before|/|q|",
                               Utilities::MPI::max(change, comm),
                               1e-12);
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  return unit_test::run(argc, argv, [](std::ostream &out) {
    check_point_pieces<2>(out);
    check_point_pieces<3>(out);
    check_increments(out);
    check_field_update(out);
    check_variance_reduction(out);
    check_match_to_stress(out);
  });
}
