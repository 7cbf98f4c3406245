#include <deal.II/distributed/p4est_wrappers.h>

#include <vefs/compat/box_mesh_locator.h>

#include <cstring>

namespace vefs
{
  namespace
  {
    template <int dim>
    unsigned int
    coarse_index(const std::array<unsigned int, dim> &n,
                 const std::array<unsigned int, dim> &i)
    {
      unsigned int index = 0;
      for (int d = dim - 1; d >= 0; --d)
        index = index * n[d] + i[d];
      return index;
    }
  } // namespace

  template <int dim>
  BoxMeshLocator<dim>::BoxMeshLocator(
    const Triangulation<dim>        &triangulation,
    const BoundingBox<dim>          &cavity,
    const std::vector<unsigned int> &subdivisions,
    const std::array<WallType, 6>   &wall_types)
    : distributed(
        dynamic_cast<const parallel::distributed::Triangulation<dim> *>(
          &triangulation))
    , cavity(cavity)
  {
    for (unsigned int d = 0; d < dim; ++d)
      periodic[d] = wall_types[2 * d] == WallType::periodic;
    for (unsigned int w = 0; w < 2 * dim; ++w)
      contact[w] = wall_types[w] == WallType::contact;
    unsigned int n_cells = 1;
    for (unsigned int d = 0; d < dim; ++d)
      {
        n_coarse[d] = subdivisions[d];
        n_cells *= subdivisions[d];
      }
    coarse_cells.resize(n_cells);
    coarse_corners.resize(n_cells);
    for (const auto &cell : triangulation.cell_iterators_on_level(0))
      {
        std::array<unsigned int, dim> i;
        for (unsigned int d = 0; d < dim; ++d)
          i[d] = static_cast<unsigned int>(
            (cell->center()[d] - cavity.lower_bound(d)) /
            cavity.side_length(d) * n_coarse[d]);
        const unsigned int index = coarse_index<dim>(n_coarse, i);
        coarse_cells[index]      = cell;
        coarse_corners[index]    = {cell->vertex(0),
                                    cell->vertex(cell->n_vertices() - 1)};
      }
  }

  template <int dim>
  std::pair<unsigned int, Point<dim>>
  BoxMeshLocator<dim>::coarse_cell_around(const Point<dim> &p) const
  {
    std::array<unsigned int, dim> i;
    Point<dim>                    in_cell;
    for (unsigned int d = 0; d < dim; ++d)
      {
        const double x =
          std::max((p[d] - cavity.lower_bound(d)) / cavity.side_length(d), 0.) *
          n_coarse[d];
        i[d] =
          std::min<unsigned int>(static_cast<unsigned int>(x), n_coarse[d] - 1);
        in_cell[d] = std::min(std::max(x - i[d], 0.), 1.);
      }
    return {coarse_index<dim>(n_coarse, i), in_cell};
  }

  template <int dim>
  typename Triangulation<dim>::active_cell_iterator
  BoxMeshLocator<dim>::locate(const Point<dim> &p) const
  {
    return locate_with_unit_point(p).cell;
  }

  template <int dim>
  typename BoxMeshLocator<dim>::CellAndUnitPoint
  BoxMeshLocator<dim>::locate_with_unit_point(const Point<dim> &p) const
  {
    const unsigned int index = coarse_cell_around(p).first;
    auto               cell  = coarse_cells[index];
    auto [lower, upper]      = coarse_corners[index];
    // Children of a hypercube are numbered lexicographically, x fastest.
    while (cell->has_children())
      {
        unsigned int child = 0;
        for (unsigned int d = 0; d < dim; ++d)
          {
            const double center = 0.5 * (lower[d] + upper[d]);
            if (p[d] >= center)
              {
                child |= (1u << d);
                lower[d] = center;
              }
            else
              upper[d] = center;
          }
        cell = cell->child(child);
      }
    Point<dim> xi;
    for (unsigned int d = 0; d < dim; ++d)
      xi[d] =
        std::min(1., std::max(0., (p[d] - lower[d]) / (upper[d] - lower[d])));
    return {cell, xi};
  }

  template <int dim>
  types::subdomain_id
  BoxMeshLocator<dim>::owner_rank(const Point<dim> &p) const
  {
    if (distributed == nullptr)
      return 0;
    using p4est                  = internal::p4est::functions<dim>;
    const auto [coarse, in_cell] = coarse_cell_around(p);
    const auto tree = distributed->get_coarse_cell_to_p4est_tree_permutation()
                        [coarse_cells[coarse]->index()];
    // A quadrant of the finest level p4est allows: coordinates multiples of
    // its length, in [0, root length). The tree's axes are the coarse
    // cell's (deal.II hands p4est the vertices in its own order).
    constexpr int finest = dim == 2 ? P4EST_QMAXLEVEL : P8EST_QMAXLEVEL;
    constexpr std::int64_t length =
      dim == 2 ? P4EST_QUADRANT_LEN(finest) : P8EST_QUADRANT_LEN(finest);
    constexpr std::int64_t        n_positions = std::int64_t(1) << finest;
    std::array<std::int32_t, dim> coordinates;
    for (unsigned int d = 0; d < dim; ++d)
      coordinates[d] = static_cast<std::int32_t>(
        length * std::min<std::int64_t>(static_cast<std::int64_t>(in_cell[d] *
                                                                  n_positions),
                                        n_positions - 1));
    typename internal::p4est::types<dim>::quadrant quadrant;
    std::memset(&quadrant, 0, sizeof(quadrant));
    quadrant.level = finest;
    quadrant.x     = coordinates[0];
    quadrant.y     = coordinates[1];
    if constexpr (dim == 3)
      quadrant.z = coordinates[dim - 1];
    // p4est declares the forest non-const; this only reads its partition.
    auto *forest = const_cast<typename internal::p4est::types<dim>::forest *>(
      distributed->get_p4est());
    return p4est::comm_find_owner(forest, tree, &quadrant, 0);
  }

  template <int dim>
  Point<dim>
  BoxMeshLocator<dim>::fold_into_cavity(const Point<dim> &p) const
  {
    Point<dim> q;
    for (unsigned int d = 0; d < dim; ++d)
      {
        const double lower = cavity.lower_bound(d);
        const double size  = cavity.side_length(d);
        if (periodic[d])
          q[d] =
            lower + (p[d] - lower) - size * std::floor((p[d] - lower) / size);
        else
          {
            const double margin = 1e-10 * size;
            q[d] =
              std::min(std::max(p[d], lower + margin), lower + size - margin);
          }
      }
    return q;
  }

  template <int dim>
  double
  BoxMeshLocator<dim>::distance_beyond_contact_walls(const Point<dim> &p) const
  {
    double distance = 0;
    for (unsigned int d = 0; d < dim; ++d)
      {
        if (contact[2 * d])
          distance = std::max(distance, cavity.lower_bound(d) - p[d]);
        if (contact[2 * d + 1])
          distance = std::max(distance, p[d] - cavity.upper_bound(d));
      }
    return distance;
  }

  template <int dim>
  Tensor<1, dim>
  BoxMeshLocator<dim>::gradient_beyond_contact_walls(
    const Point<dim>     &p,
    const Tensor<1, dim> &g) const
  {
    Tensor<1, dim> gradient = g;
    for (unsigned int d = 0; d < dim; ++d)
      if ((contact[2 * d] && p[d] < cavity.lower_bound(d)) ||
          (contact[2 * d + 1] && p[d] > cavity.upper_bound(d)))
        gradient[d] = 0;
    return gradient;
  }

  template <int dim>
  bool
  BoxMeshLocator<dim>::touches_contact_wall(
    const typename Triangulation<dim>::active_cell_iterator &cell) const
  {
    const Point<dim> lower = cell->vertex(0);
    const Point<dim> upper =
      cell->vertex(GeometryInfo<dim>::vertices_per_cell - 1);
    for (unsigned int d = 0; d < dim; ++d)
      {
        const double margin = 1e-10 * cavity.side_length(d);
        if ((contact[2 * d] && lower[d] < cavity.lower_bound(d) + margin) ||
            (contact[2 * d + 1] && upper[d] > cavity.upper_bound(d) - margin))
          return true;
      }
    return false;
  }

  template <int dim>
  Point<dim>
  BoxMeshLocator<dim>::unit_point(
    const typename Triangulation<dim>::active_cell_iterator &cell,
    const Point<dim>                                        &p)
  {
    const Point<dim> lower = cell->vertex(0);
    const Point<dim> upper =
      cell->vertex(GeometryInfo<dim>::vertices_per_cell - 1);
    Point<dim> xi;
    for (unsigned int d = 0; d < dim; ++d)
      xi[d] =
        std::min(1., std::max(0., (p[d] - lower[d]) / (upper[d] - lower[d])));
    return xi;
  }

  template class BoxMeshLocator<2>;
  template class BoxMeshLocator<3>;
} // namespace vefs
