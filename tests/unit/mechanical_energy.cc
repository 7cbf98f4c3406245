// mechanical_energy() (stress/mechanical_energy.h), the energy budget's
// measure, against exact energies: the liquid below the plane y = 0.23 of
// the cavity [-1, 1]^dim (cut through the middle of cells, on a mesh with
// hanging nodes near the surface), with a uniform velocity u and a uniform
// stress sigma. The Q1 fields are then exact, and the cut-cell quadrature
// integrates polynomials of degree 1 exactly, so
//   kinetic   = rho |u|^2 / 2 V,
//   potential = -rho g . (first moment of the liquid),
//   elastic   = G / 2 (tr c - dim - ln det c) V,   c = I + sigma / G,
// with V and the first moment of the box [-1, 1]^(dim-1) x [-1, 0.23].
// Tolerance: relative error below 1e-12 (round-off of the sums over the
// cells and of the quadrature generator's root finding). 1 and 2 ranks.

#include "unit_test.h"

#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/grid/grid_generator.h>

#include <vefs/stress/mechanical_energy.h>

#include <cmath>
#include <iostream>

using namespace dealii;

namespace
{
  template <int dim>
  void
  check(std::ostream &out)
  {
    const double                              height = 0.23;
    parallel::distributed::Triangulation<dim> triangulation(MPI_COMM_WORLD);
    Point<dim>                                lower, upper;
    for (unsigned int d = 0; d < dim; ++d)
      {
        lower[d] = -1;
        upper[d] = 1;
      }
    GridGenerator::subdivided_hyper_rectangle(triangulation,
                                              std::vector<unsigned int>(dim, 2),
                                              lower,
                                              upper,
                                              true);
    triangulation.refine_global(2);
    // One level more near the surface on one side: hanging nodes.
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned() &&
          std::abs(cell->center()[dim - 1] - height) < cell->diameter() &&
          cell->center()[0] < 0)
        cell->set_refine_flag();
    triangulation.execute_coarsening_and_refinement();

    vefs::MaterialParameters material;
    material.density           = 800;
    material.polymer_viscosity = 10;
    material.relaxation_time   = 0.005; // G = 2000 Pa
    material.alpha             = 0;
    material.gravity           = std::vector<double>(dim, 0.);
    material.gravity[0]        = 1.5;
    material.gravity[dim - 1]  = -9.81;
    const vefs::Rheology<dim> rheology(material, vefs::StressParameters(), 0);

    Tensor<1, dim> u;
    for (unsigned int d = 0; d < dim; ++d)
      u[d] = 0.3 - 0.2 * d;
    SymmetricTensor<2, dim> sigma;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = i; j < dim; ++j)
        sigma[i][j] = i == j ? 300. * (i + 1) : -150.;

    vefs::TransportedFields<dim> fields(triangulation, true, false, {});
    fields.setup_dofs();
    const ScalarFunctionFromFunctionObject<dim> level_set(
      [&](const Point<dim> &p) { return p[dim - 1] - height; });
    const Functions::ConstantFunction<dim> velocity(
      std::vector<double>(u.begin_raw(), u.end_raw()));
    std::vector<double> stress_values;
    for (unsigned int k = 0;
         k < SymmetricTensor<2, dim>::n_independent_components;
         ++k)
      stress_values.push_back(
        sigma.access_raw_entry(k)); // unrolled order of the fields
    const Functions::ConstantFunction<dim> stress(stress_values);
    fields.interpolate(level_set, velocity, &stress);
    const vefs::LiquidDomain<dim> domain(fields);

    const vefs::MechanicalEnergy energy =
      vefs::mechanical_energy(fields, domain, material, rheology);

    // The box [-1, 1]^(dim-1) x [-1, height].
    const double   side   = std::pow(2., dim - 1);
    const double   volume = side * (height + 1);
    Tensor<1, dim> moment;
    moment[dim - 1] = side * (height * height - 1) / 2;
    Tensor<1, dim> g;
    for (unsigned int d = 0; d < dim; ++d)
      g[d] = material.gravity[d];
    const double                  G = rheology.shear_modulus();
    const SymmetricTensor<2, dim> c = unit_symmetric_tensor<dim>() + sigma / G;
    const double kinetic   = 0.5 * material.density * u.norm_square() * volume;
    const double potential = -material.density * (g * moment);
    const double elastic =
      0.5 * G * (trace(c) - dim - std::log(determinant(c))) * volume;

    const std::string name = std::to_string(dim) + "D ";
    unit_test::check_below(out,
                           name + "kinetic, relative error",
                           std::abs(energy.kinetic - kinetic) / kinetic,
                           1e-12);
    unit_test::check_below(out,
                           name + "potential, relative error",
                           std::abs(energy.potential - potential) /
                             std::abs(potential),
                           1e-12);
    unit_test::check_below(out,
                           name + "elastic, relative error",
                           std::abs(energy.elastic - elastic) / elastic,
                           1e-12);
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
