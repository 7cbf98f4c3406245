#ifndef vefs_cavity_h
#define vefs_cavity_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <array>
#include <string>
#include <vector>

namespace vefs
{
  /** A point from the comma-separated coordinates of an entry. */
  template <int dim>
  dealii::Point<dim>
  to_point(const std::vector<double> &coordinates)
  {
    dealii::Point<dim> p;
    for (unsigned int d = 0; d < dim; ++d)
      p[d] = coordinates[d];
    return p;
  }

  /** What a cavity wall does to the liquid that touches it. */
  enum class WallType
  {
    no_slip,
    slip,
    open,
    velocity,
    periodic,
    contact
  };

  /** Names of the cavity walls, in boundary-id order. */
  const std::array<std::string, 6> wall_names = {
    {"x-", "x+", "y-", "y+", "z-", "z+"}};

  /**
   * The box that holds the scene and its walls: subsections "Cavity" and
   * "Walls". The defaults are those of the default scene (doc/broken_dam.md).
   */
  struct CavityParameters
  {
    /** The entries, bound to the members below. */
    void
    declare(dealii::ParameterHandler &prm);

    /** Throws InputError for an entry that a @p dimension-D scene cannot use.
     */
    void
    check(const unsigned int dimension) const;

    /**
     * Whether @p p lies on a slip or a contact wall, the walls that hold
     * the normal velocity only (to 1e-10 of the cavity's extent).
     */
    template <int dim>
    bool
    on_slip_or_contact_wall(const dealii::Point<dim> &p) const;

    /** Whether a wall of a @p dimension-D scene is a contact wall. */
    bool
    has_contact_walls(const unsigned int dimension) const;

    /** Coordinate directions whose two walls are periodic. */
    std::vector<unsigned int>
    periodic_directions() const;

    /**
     * The shortest edge of a cell refined @p level times from the coarse
     * cells (after check()).
     */
    double
    cell_size(const unsigned int dimension, const unsigned int level) const;

    std::vector<double>       cavity_lower        = {0, 0};
    std::vector<double>       cavity_upper        = {0.28575, 0.142875};
    std::vector<unsigned int> coarse_subdivisions = {2, 1};

    std::array<WallType, 6> wall_type = {{WallType::slip,
                                          WallType::slip,
                                          WallType::slip,
                                          WallType::open,
                                          WallType::slip,
                                          WallType::open}};
    /** Used where wall_type is 'velocity': muParser expressions in x, t. */
    std::array<std::string, 6> wall_velocity = {
      {"0; 0", "0; 0", "0; 0", "0; 0", "0; 0", "0; 0"}};
  };
} // namespace vefs

#endif
