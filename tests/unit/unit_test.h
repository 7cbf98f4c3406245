#ifndef vefs_unit_test_h
#define vefs_unit_test_h

// Helpers shared by the unit tests (tests/README.md, "Unit tests"): what a
// test prints must not depend on round-off, so errors are printed as
// "below BOUND" when they are, and by value (which the expected output
// does not hold) when they are not.

#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/grid/grid_generator.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <iomanip>
#include <iostream>
#include <ostream>
#include <sstream>
#include <string>

namespace unit_test
{
  /**
   * The main() of a unit test: MPI started, @p checks writes the output,
   * which rank 0 prints (so that 1 and 2 ranks print the same).
   */
  template <typename Checks>
  int
  run(int argc, char **argv, const Checks &checks)
  {
    dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
    std::ostringstream                       text;
    checks(text);
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::cout << text.str();
    return 0;
  }

  /** The 2D simple shear u = (gdot y, 0) of the stress update tests. */
  class SimpleShear : public dealii::Function<2>
  {
  public:
    explicit SimpleShear(const double rate)
      : dealii::Function<2>(2)
      , rate(rate)
    {
    }

    double
    value(const dealii::Point<2> &p,
          const unsigned int      component) const override
    {
      return component == 0 ? rate * p[1] : 0.;
    }

  private:
    const double rate;
  };

  /** "label: below bound", or "label: VALUE, NOT below bound". */
  inline void
  check_below(std::ostream      &out,
              const std::string &label,
              const double       error,
              const double       bound)
  {
    // To see the values themselves when checking a bound by hand.
    if (std::getenv("VEFS_UNIT_VERBOSE"))
      std::cerr << label << ": " << std::setprecision(3) << error << '\n';
    out << label << ": ";
    if (error < bound)
      out << "below " << bound << '\n';
    else
      out << std::setprecision(3) << error << ", NOT below " << bound << '\n';
  }

  /** "label: 0", or "label: VALUE (NOT zero)". */
  inline void
  check_zero(std::ostream &out, const std::string &label, const double value)
  {
    out << label << ": ";
    if (value == 0)
      out << "0\n";
    else
      out << std::setprecision(17) << value << " (NOT zero)\n";
  }
  /**
   * A smooth field with @p n_components components, different in each
   * component and direction (sines, not a polynomial that Q1 or Hermite
   * interpolation would reproduce); @p shift makes another one.
   */
  template <int dim>
  class Smooth : public dealii::Function<dim>
  {
  public:
    Smooth(const unsigned int n_components, const double shift)
      : dealii::Function<dim>(n_components)
      , shift(shift)
    {
    }

    double
    value(const dealii::Point<dim> &p,
          const unsigned int        component) const override
    {
      double result = shift + 0.1 * component;
      for (unsigned int d = 0; d < dim; ++d)
        result += std::sin((1.7 + 0.3 * component + d) * p[d] + shift);
      return result;
    }

  private:
    const double shift;
  };

  /** The point (value, ..., value). */
  template <int dim>
  dealii::Point<dim>
  filled(const double value)
  {
    dealii::Point<dim> p;
    for (unsigned int d = 0; d < dim; ++d)
      p[d] = value;
    return p;
  }

  /**
   * [-1, 1]^dim from 2^dim coarse cells, boundary ids by face. Returns the
   * coarse subdivisions (for a BoxMeshLocator).
   */
  template <int dim>
  std::vector<unsigned int>
  make_box(dealii::parallel::distributed::Triangulation<dim> &triangulation)
  {
    const std::vector<unsigned int> subdivisions(dim, 2);
    dealii::GridGenerator::subdivided_hyper_rectangle(triangulation,
                                                      subdivisions,
                                                      filled<dim>(-1),
                                                      filled<dim>(1),
                                                      true);
    return subdivisions;
  }

  /**
   * make_box() refined twice, then twice more where the zero set of @p psi
   * is nearer than a cell's diameter to its centre, the second time for
   * x < 0.2 only: hanging nodes on the surface psi = 0, cells of three
   * sizes along it.
   */
  template <int dim>
  void
  make_box_refined_around(
    dealii::parallel::distributed::Triangulation<dim>       &triangulation,
    const std::function<double(const dealii::Point<dim> &)> &psi)
  {
    make_box(triangulation);
    triangulation.refine_global(2);
    for (unsigned int cycle = 0; cycle < 2; ++cycle)
      {
        for (const auto &cell : triangulation.active_cell_iterators())
          if (cell->is_locally_owned() &&
              std::abs(psi(cell->center())) < cell->diameter() &&
              (cycle == 0 || cell->center()[0] < 0.2))
            cell->set_refine_flag();
        triangulation.execute_coarsening_and_refinement();
      }
  }

  /**
   * make_box() refined 3 times (2D) or twice (3D), and the cells with
   * x > 0.1 and y > -0.3 once more: paths across it cross hanging nodes
   * (and, on 2 ranks, the partition). Returns the coarse subdivisions.
   */
  template <int dim>
  std::vector<unsigned int>
  make_box_with_finer_patch(
    dealii::parallel::distributed::Triangulation<dim> &triangulation)
  {
    const auto subdivisions = make_box(triangulation);
    triangulation.refine_global(dim == 2 ? 3 : 2);
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned() && cell->center()[0] > 0.1 &&
          cell->center()[1] > -0.3)
        cell->set_refine_flag();
    triangulation.execute_coarsening_and_refinement();
    return subdivisions;
  }

  /** @p value with few digits, for labels. */
  inline std::string
  text(const double value)
  {
    std::ostringstream out;
    out << value;
    return out.str();
  }
  /**
   * Three rounds of refinement of the cells within three diameters of the
   * circle (sphere) |x| = 0.7: on the unit square refined once, the level-1
   * cells near it then hold subtrees of depth 2 and 3.
   */
  template <typename TriangulationType>
  void
  refine_toward_circle(TriangulationType &triangulation)
  {
    for (unsigned int round = 0; round < 3; ++round)
      {
        for (const auto &cell : triangulation.active_cell_iterators())
          if (cell->is_locally_owned() &&
              std::abs(cell->center().norm() - 0.7) < 3 * cell->diameter())
            cell->set_refine_flag();
        triangulation.execute_coarsening_and_refinement();
      }
  }

  /** A circle's signed distance, negative inside (in the liquid). */
  class CircleDistance : public dealii::Function<2>
  {
  public:
    CircleDistance(const dealii::Point<2> &centre, const double radius)
      : centre(centre)
      , radius(radius)
    {
    }

    double
    value(const dealii::Point<2> &p, const unsigned int) const override
    {
      return p.distance(centre) - radius;
    }

  private:
    const dealii::Point<2> centre;
    const double           radius;
  };

  /**
   * The lowest level, over all ranks, of the cells that the zero set of
   * @p psi crosses: its values at their vertices take both signs.
   */
  template <int dim>
  unsigned int
  coarsest_cut_level(
    const dealii::parallel::distributed::Triangulation<dim> &triangulation,
    const dealii::Function<dim>                             &psi)
  {
    unsigned int coarsest = dealii::numbers::invalid_unsigned_int;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          bool inside = false, outside = false;
          for (const unsigned int v : cell->vertex_indices())
            {
              const double value = psi.value(cell->vertex(v));
              inside |= value < 0;
              outside |= value > 0;
            }
          if (inside && outside)
            coarsest =
              std::min(coarsest, static_cast<unsigned int>(cell->level()));
        }
    return dealii::Utilities::MPI::min(coarsest,
                                       triangulation.get_communicator());
  }
} // namespace unit_test

#endif
