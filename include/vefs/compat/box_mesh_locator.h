#ifndef vefs_box_mesh_locator_h
#define vefs_box_mesh_locator_h

#include <deal.II/base/bounding_box.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/grid/tria.h>

#include <vefs/base/cavity.h>

#include <vector>

namespace vefs
{
  using namespace dealii;

  /**
   * Finds the active cell around a point of a box-shaped cavity meshed by
   * isotropic refinement of a regular grid of axis-aligned coarse cells: the
   * coarse cell follows from the coordinates, each child from a comparison
   * with its parent's center, which halving the coarse cell's bounds gives
   * without reading vertices. Cost: one step per level, no search structure
   * to rebuild after the mesh changes (general locators such as
   * RemotePointEvaluation rebuild theirs at every call).
   */
  template <int dim>
  class BoxMeshLocator
  {
  public:
    BoxMeshLocator(const Triangulation<dim>        &triangulation,
                   const BoundingBox<dim>          &cavity,
                   const std::vector<unsigned int> &subdivisions,
                   const std::array<WallType, 6>   &wall_types);

    /**
     * The point of the cavity that stands for @p p: wrapped around in the
     * periodic directions, moved back onto the walls (a hair inside) in the
     * others.
     */
    Point<dim>
    fold_into_cavity(const Point<dim> &p) const;

    /**
     * How far @p p lies beyond a contact wall, 0 if it does not: the liquid
     * may leave such a wall, and what comes from beyond it is empty.
     */
    double
    distance_beyond_contact_walls(const Point<dim> &p) const;

    /**
     * The gradient at @p p of a field f extended beyond the contact walls
     * by f(fold_into_cavity(p)), given the gradient @p g of f at the
     * folded point: constant across a contact wall, the extension has no
     * derivative along the wall's normal.
     */
    Tensor<1, dim>
    gradient_beyond_contact_walls(const Point<dim>     &p,
                                  const Tensor<1, dim> &g) const;

    /** Whether a face of the axis-aligned @p cell lies on a contact wall. */
    bool
    touches_contact_wall(
      const typename Triangulation<dim>::active_cell_iterator &cell) const;

    /** The active cell containing @p p; it may be artificial on this rank. */
    typename Triangulation<dim>::active_cell_iterator
    locate(const Point<dim> &p) const;

    /** An active cell and a point's coordinates in its unit cell. */
    struct CellAndUnitPoint
    {
      typename Triangulation<dim>::active_cell_iterator cell;
      Point<dim>                                        unit_point;
    };

    /**
     * locate() and unit_point() at once, the unit point from the bounds the
     * walk down the tree halves (the same to round-off; reading the cell's
     * vertices cost a fifth of the 3D transport's advection).
     */
    CellAndUnitPoint
    locate_with_unit_point(const Point<dim> &p) const;

    /**
     * The MPI rank that owns the active cell containing @p p (the cavity's
     * point fold_into_cavity() gives), from p4est's partition: the position
     * of p in its coarse cell as a quadrant of p4est's finest level, looked
     * up among the ranks' first quadrants. No messages, O(log ranks).
     * (deal.II 9.4's find_point_owner_rank() tests every point against
     * every tree: with the 6,000 coarse cells of the 3D ball, 11.5 % of the
     * first 3 steps at 2.5 mm.) 0 if the triangulation is not distributed.
     */
    types::subdomain_id
    owner_rank(const Point<dim> &p) const;

    /** Coordinates of @p p in the unit cell of the axis-aligned @p cell. */
    static Point<dim>
    unit_point(const typename Triangulation<dim>::active_cell_iterator &cell,
               const Point<dim>                                        &p);

    /**
     * Weight of vertex @p v in the Q1 interpolation at the unit-cell point
     * @p xi (vertex v has the unit coordinates given by its bits).
     */
    static double
    vertex_weight(const Point<dim> &xi, const unsigned int v)
    {
      double weight = 1;
      for (unsigned int d = 0; d < dim; ++d)
        weight *= ((v >> d) & 1) ? xi[d] : 1 - xi[d];
      return weight;
    }

  private:
    /**
     * The coarse cell around @p p (index into coarse_cells), and p's
     * coordinates in it, each in [0, 1].
     */
    std::pair<unsigned int, Point<dim>>
    coarse_cell_around(const Point<dim> &p) const;

    /** Null if the triangulation is not a parallel::distributed one. */
    const parallel::distributed::Triangulation<dim>        *distributed;
    const BoundingBox<dim>                                  cavity;
    std::array<unsigned int, dim>                           n_coarse;
    std::array<bool, dim>                                   periodic;
    std::array<bool, 2 * dim>                               contact;
    std::vector<typename Triangulation<dim>::cell_iterator> coarse_cells;
    /** The lowest and the highest corner of each coarse cell. */
    std::vector<std::pair<Point<dim>, Point<dim>>> coarse_corners;
  };
} // namespace vefs

#endif
