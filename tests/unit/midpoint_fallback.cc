// midpoint_fallback_box() and corner_liquid_fraction() (midpoint_fallback.h),
// and the liquid volume they make continuous (sharp_liquid_volume()).
// - corner_liquid_fraction() on the unit box: psi = x - 0.3 gives 0.3 and
//   derivative -1 (exact for a level set linear along one axis), psi = x + 1
//   nothing, psi = x - 2 everything (1e-15).
// - deal.II's QuadratureGenerator (deal.II's four splits in 3D, vefs's
//   twelve in 2D) on the unit box cut by psi = (x - 0.3)(y - 0.6), whose
//   gradient vanishes on the surface along the line (0.3, 0.6, z): the
//   points recognized as the midpoint fallback's lie in boxes of volume
//   2^-splits around that line (point); a plane cut (no saddle) has none.
// - The liquid volume of one cell cut by the same psi + c, c over +-1e-3
//   in steps of 1e-6 (2D) and over +-0.03 in steps of 3e-5 (3D):
//   continuous, its largest change from one step to the next below 1e-4
//   (2D) and 1e-3 (3D). Exact: -dV/dc = int 1/|grad psi| over the surface,
//   at most 2 ln(0.42 / |c|) + 4, so a step changes V by about 3e-5 (2D)
//   and 7e-4 (3D) at most; a midpoint box jumps by 2^-12 of the cell in 2D
//   and, spanning the cell's cross-section, by the whole cell in 3D (psi =
//   -0.02 at the centres of its sixteen 1 x 1 x 1/16 boxes).
// One cell, 1 and 2 ranks.

#include "unit_test.h"

#include <deal.II/base/function_signed_distance.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/hp/q_collection.h>
#include <deal.II/non_matching/quadrature_generator.h>

#include <vefs/transport/liquid_domain.h>
#include <vefs/transport/midpoint_fallback.h>

#include <cmath>
#include <string>

using namespace dealii;

namespace
{
  /** psi = (x - 0.3)(y - 0.6) + shift: a saddle on its zero surface. */
  template <int dim>
  class Saddle : public Function<dim>
  {
  public:
    double
    value(const Point<dim> &p, const unsigned int = 0) const override
    {
      return (p[0] - 0.3) * (p[1] - 0.6);
    }

    Tensor<1, dim>
    gradient(const Point<dim> &p, const unsigned int = 0) const override
    {
      Tensor<1, dim> g;
      g[0] = p[1] - 0.6;
      g[1] = p[0] - 0.3;
      return g;
    }

    SymmetricTensor<2, dim>
    hessian(const Point<dim> &, const unsigned int = 0) const override
    {
      SymmetricTensor<2, dim> h;
      h[0][1] = 1;
      return h;
    }
  };

  template <int dim>
  void
  check_fraction(std::ostream &out)
  {
    Point<dim> upper;
    for (unsigned int d = 0; d < dim; ++d)
      upper[d] = 1;
    const BoundingBox<dim> unit_box(std::make_pair(Point<dim>(), upper));
    const std::string      label = std::to_string(dim) + "D, corner fraction, ";
    for (const auto &[offset, name] : {std::make_pair(-0.3, "x - 0.3"),
                                       std::make_pair(1., "x + 1"),
                                       std::make_pair(-2., "x - 2")})
      {
        Tensor<1, dim> normal;
        normal[0] = 1;
        const Functions::SignedDistance::Plane<dim> plane(Point<dim>() -
                                                            offset * normal,
                                                          normal);
        double                                      derivative = 0;
        const double                                fraction =
          vefs::corner_liquid_fraction<dim>(plane, unit_box, derivative);
        const double exact_fraction = std::clamp(-offset, 0., 1.);
        const double exact_slope    = (offset < 0 && offset > -1) ? -1. : 0.;
        unit_test::check_below(out,
                               label + "psi = " + name,
                               std::abs(fraction - exact_fraction) +
                                 std::abs(derivative - exact_slope),
                               1e-15);
      }
  }

  template <int dim>
  void
  check_recognized(std::ostream &out)
  {
    const unsigned int                    splits = dim == 2 ? 12 : 4;
    const hp::QCollection<1>              gauss(QGauss<1>(2));
    NonMatching::QuadratureGenerator<dim> generator(
      gauss,
      NonMatching::AdditionalQGeneratorData(splits));
    Point<dim> upper;
    for (unsigned int d = 0; d < dim; ++d)
      upper[d] = 1;
    const BoundingBox<dim> unit_box(std::make_pair(Point<dim>(), upper));
    const std::string      label = std::to_string(dim) + "D, generator, ";

    generator.generate(Saddle<dim>(), unit_box);
    unsigned int recognized = 0, misplaced = 0;
    for (const Quadrature<dim> *rule : {&generator.get_inside_quadrature(),
                                        &generator.get_outside_quadrature()})
      for (unsigned int q = 0; q < rule->size(); ++q)
        if (const auto box = vefs::midpoint_fallback_box(rule->point(q),
                                                         rule->weight(q),
                                                         splits))
          {
            ++recognized;
            if (std::getenv("VEFS_UNIT_VERBOSE"))
              std::cerr << "midpoint box at " << box->center() << ", psi there "
                        << Saddle<dim>().value(box->center()) << '\n';
            Point<dim> saddle = box->center();
            saddle[0]         = 0.3;
            saddle[1]         = 0.6;
            if (!box->point_inside(saddle) ||
                box->volume() != std::ldexp(1., -static_cast<int>(splits)))
              ++misplaced;
          }
    out << label
        << "saddle: midpoint boxes found: " << (recognized > 0 ? "yes" : "no")
        << ", all of volume 2^-splits around the saddle: "
        << (misplaced == 0 ? "yes" : "no") << '\n';

    Tensor<1, dim> normal;
    for (unsigned int d = 0; d < dim; ++d)
      normal[d] = 0.2 + 0.3 * d;
    generator.generate(Functions::SignedDistance::Plane<dim>(
                         Point<dim>() + 0.5 * normal / normal.norm(),
                         normal / normal.norm()),
                       unit_box);
    recognized = 0;
    for (const Quadrature<dim> *rule : {&generator.get_inside_quadrature(),
                                        &generator.get_outside_quadrature()})
      for (unsigned int q = 0; q < rule->size(); ++q)
        if (vefs::midpoint_fallback_box(rule->point(q),
                                        rule->weight(q),
                                        splits))
          ++recognized;
    out << label << "plane: points recognized: " << recognized << '\n';
  }

  template <int dim>
  void
  check_continuity(std::ostream &out)
  {
    parallel::distributed::Triangulation<dim> triangulation(MPI_COMM_WORLD);
    GridGenerator::hyper_cube(triangulation, 0, 1);
    vefs::TransportedFields<dim> fields(triangulation, false, false, {});
    fields.setup_dofs();
    const Saddle<dim> saddle;
    for (const auto &node : fields.nodes())
      fields.set_level_set(node, saddle.value(node.point));
    fields.finalize();

    // The midpoint boxes are 2^-12 of the cell in 2D, 1/16 in 3D, where the
    // generator splits along z only: the cell's whole cross-section, psi =
    // -0.02 at their centres.
    const double range          = dim == 2 ? 1e-3 : 3e-2;
    const double step           = range / 1000;
    double       largest_change = 0;
    double       previous = vefs::sharp_liquid_volume(fields, -range).volume;
    for (int k = -999; k <= 1000; ++k)
      {
        const double volume =
          vefs::sharp_liquid_volume(fields, k * step).volume;
        largest_change = std::max(largest_change, std::abs(volume - previous));
        previous       = volume;
      }
    if (std::getenv("VEFS_UNIT_VERBOSE"))
      std::cerr << "volume at shift 0 - exact: "
                << vefs::sharp_liquid_volume(fields, 0).volume - 0.54 << '\n';
    unit_test::check_below(out,
                           std::to_string(dim) +
                             "D, one cell, largest volume change per step",
                           largest_change,
                           dim == 2 ? 1e-4 : 1e-3);
  }
} // namespace

int
main(int argc, char **argv)
{
  return unit_test::run(argc, argv, [](std::ostream &out) {
    check_fraction<2>(out);
    check_fraction<3>(out);
    check_recognized<2>(out);
    check_recognized<3>(out);
    check_continuity<2>(out);
    check_continuity<3>(out);
  });
}
