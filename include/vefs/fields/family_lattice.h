#ifndef vefs_family_lattice_h
#define vefs_family_lattice_h

#include <deal.II/base/point.h>
#include <deal.II/base/utilities.h>

namespace vefs
{
  using namespace dealii;

  /**
   * The vertices of the children of a refined cell (a family): a lattice of
   * 3^dim points, numbered sum_d a_d 3^d where a_d = 0, 1, 2 is the offset
   * in direction d in half cells of the parent. The mesh transfer carries
   * values at these points (VertexFieldTransfer::LatticeSource).
   */
  template <int dim>
  struct FamilyLattice
  {
    static constexpr unsigned int n_points = dim == 2 ? 9 : 27;

    /** The lattice point of vertex @p v of child @p child. */
    static unsigned int
    point(const unsigned int child, const unsigned int v)
    {
      unsigned int index = 0, stride = 1;
      for (unsigned int d = 0; d < dim; ++d, stride *= 3)
        index += stride * (((child >> d) & 1) + ((v >> d) & 1));
      return index;
    }

    /** Lattice point @p i in the parent's unit cell. */
    static Point<dim>
    unit_point(const unsigned int i)
    {
      Point<dim> xi;
      for (unsigned int d = 0, rest = i; d < dim; ++d, rest /= 3)
        xi[d] = 0.5 * (rest % 3);
      return xi;
    }
  };
} // namespace vefs

#endif
