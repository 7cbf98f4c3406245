#ifndef vefs_shadow_holes_h
#define vefs_shadow_holes_h

#include <vefs/base/cavity.h>
#include <vefs/fields/transported_fields.h>

namespace vefs
{
  /**
   * The area (length in 2D) of the holes in the liquid seen from above
   * (along the last coordinate, onto the cavity's lowest face in it, the
   * floor): the liquid's shadow on the floor is the footprint of the cells
   * that hold liquid (a vertex with a negative level set); a hole is floor
   * outside the shadow that the shadow encloses. A ball spread into a sheet
   * that tears and gathers into a ring has one; a sheet lifted off the
   * floor or leaving the corners dry has none
   * (doc/bouncing_ball_3d_study.md).
   *
   * Each rank draws the shadow of its cells on a raster of the smallest
   * liquid cell's footprint over the whole floor, the ranks' rasters are
   * merged, and the raster cells outside the shadow that cannot be reached
   * from the floor's edge without crossing it are the holes. Exact for a
   * shadow whose edges run along the cells.
   */
  template <int dim>
  double
  shadow_holes(const TransportedFields<dim> &fields,
               const CavityParameters       &cavity);
} // namespace vefs

#endif
