#ifndef vefs_midpoint_fallback_h
#define vefs_midpoint_fallback_h

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/function.h>
#include <deal.II/base/point.h>

#include <optional>
#include <vector>

namespace vefs
{
  using namespace dealii;

  /**
   * deal.II's NonMatching::QuadratureGenerator splits a box in halves until
   * it finds a height direction; after its last allowed split it falls back
   * to one point at the box's centre with the box's volume as weight,
   * counted wholly inside or outside by the sign of the level set there.
   * Near a saddle of the level set (a point or line where its gradient
   * vanishes on the surface) the liquid volume then jumps as the surface
   * passes that centre (doc/time_step_surface.md, step 4).
   *
   * Such a point on the reference cell [0,1]^dim, split in halves at most
   * @p max_box_splits times, is recognized by its coordinates, odd
   * multiples of half a power of two, and its weight, the product of the
   * sides those give. Returns the sub-box, or nothing for any other point
   * (a Gauss point is never such a multiple).
   */
  template <int dim>
  std::optional<BoundingBox<dim>>
  midpoint_fallback_box(const Point<dim>  &point,
                        const double       weight,
                        const unsigned int max_box_splits);

  /**
   * The liquid fraction of @p box, {psi < 0}, estimated from the values of
   * @p level_set at its corners as -min / (max - min), clipped to [0, 1]:
   * exact for a level set linear along one axis, 0 or 1 where the corners
   * agree, and continuous and monotone under a shift psi + c, which the
   * midpoint's 0 or 1 is not. @p derivative receives its derivative with
   * respect to c.
   */
  template <int dim>
  double
  corner_liquid_fraction(const Function<dim>    &level_set,
                         const BoundingBox<dim> &box,
                         double                 &derivative);

  /**
   * A quadrature of the liquid part of @p box for the midpoint fallback's
   * points: the box cut into @p n^dim equal sub-boxes, each one point at its
   * centre weighted by its corner_liquid_fraction() (deal.II's generator
   * splits a cube along one axis only, so the fallback boxes can span the
   * whole cell across). Appends to @p points and @p weights and adds the
   * derivative of the weights' sum with respect to a shift of the level set
   * to @p derivative.
   */
  template <int dim>
  void
  append_corner_quadrature(const Function<dim>     &level_set,
                           const BoundingBox<dim>  &box,
                           const unsigned int       n,
                           std::vector<Point<dim>> &points,
                           std::vector<double>     &weights,
                           double                  &derivative);
} // namespace vefs

#endif
