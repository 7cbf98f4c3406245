#include <deal.II/base/mpi.h>

#include <vefs/io/shadow_holes.h>

#include <array>
#include <cmath>
#include <deque>
#include <limits>

namespace vefs
{
  template <int dim>
  double
  shadow_holes(const TransportedFields<dim> &fields,
               const CavityParameters       &cavity)
  {
    constexpr unsigned int vertical = dim - 1;
    const MPI_Comm         comm =
      fields.dof_handler.get_triangulation().get_communicator();
    const auto holds_liquid = [&](const auto &cell) {
      for (const unsigned int v : cell->vertex_indices())
        if (fields.level_set_at(cell, v) < 0)
          return true;
      return false;
    };

    // The footprints of the owned cells that hold liquid (the cells are
    // boxes: vertex 0 is the lower corner, the last vertex the upper one),
    // and the smallest one's size: the raster's cells.
    std::vector<std::pair<Point<dim>, Point<dim>>> footprints;
    std::array<double, 2> size{{std::numeric_limits<double>::max(), 1}};
    if (vertical == 2)
      size[1] = size[0];
    for (const auto &cell : fields.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && holds_liquid(cell))
        {
          footprints.emplace_back(cell->vertex(0),
                                  cell->vertex(cell->n_vertices() - 1));
          for (unsigned int d = 0; d < vertical; ++d)
            size[d] = std::min(size[d],
                               footprints.back().second[d] -
                                 footprints.back().first[d]);
        }
    for (unsigned int d = 0; d < vertical; ++d)
      size[d] = Utilities::MPI::min(size[d], comm);
    if (size[0] == std::numeric_limits<double>::max())
      return 0;

    // The raster over the floor, numbered x first.
    std::array<unsigned int, 2> n{{1, 1}};
    for (unsigned int d = 0; d < vertical; ++d)
      n[d] = static_cast<unsigned int>(std::lround(
        (cavity.cavity_upper[d] - cavity.cavity_lower[d]) / size[d]));
    const auto raster_index = [&](const double x, const unsigned int d) {
      return static_cast<unsigned int>(
        std::lround((x - cavity.cavity_lower[d]) / size[d]));
    };
    enum : unsigned char
    {
      uncovered,
      shadow,
      reached
    };
    std::vector<unsigned char> raster(static_cast<std::size_t>(n[0]) * n[1],
                                      uncovered);
    for (const auto &[lower, upper] : footprints)
      {
        std::array<unsigned int, 2> first{{0, 0}}, end{{1, 1}};
        for (unsigned int d = 0; d < vertical; ++d)
          {
            first[d] = raster_index(lower[d], d);
            end[d]   = raster_index(upper[d], d);
          }
        for (unsigned int j = first[1]; j < end[1]; ++j)
          for (unsigned int i = first[0]; i < end[0]; ++i)
            raster[i + static_cast<std::size_t>(n[0]) * j] = shadow;
      }
    const int ierr = MPI_Allreduce(MPI_IN_PLACE,
                                   raster.data(),
                                   raster.size(),
                                   MPI_UNSIGNED_CHAR,
                                   MPI_MAX,
                                   comm);
    AssertThrowMPI(ierr);

    // Flood the uncovered floor from its edge (every rank alike).
    std::deque<std::size_t> front;
    const auto              reach = [&](const std::size_t k) {
      if (raster[k] == uncovered)
        {
          raster[k] = reached;
          front.push_back(k);
        }
    };
    for (unsigned int j = 0; j < n[1]; ++j)
      for (unsigned int i = 0; i < n[0]; ++i)
        if (i == 0 || i + 1 == n[0] ||
            (vertical == 2 && (j == 0 || j + 1 == n[1])))
          reach(i + static_cast<std::size_t>(n[0]) * j);
    while (!front.empty())
      {
        const std::size_t  k = front.front();
        const unsigned int i = k % n[0], j = k / n[0];
        front.pop_front();
        if (i > 0)
          reach(k - 1);
        if (i + 1 < n[0])
          reach(k + 1);
        if (j > 0)
          reach(k - n[0]);
        if (j + 1 < n[1])
          reach(k + n[0]);
      }

    std::size_t holes = 0;
    for (const unsigned char state : raster)
      holes += state == uncovered;
    return holes * size[0] * size[1];
  }

  template double
  shadow_holes(const TransportedFields<2> &, const CavityParameters &);
  template double
  shadow_holes(const TransportedFields<3> &, const CavityParameters &);
} // namespace vefs
