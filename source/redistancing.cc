#include <deal.II/base/mpi.h>
#include <deal.II/numerics/rtree.h>

#include <vefs/redistancing.h>

namespace vefs
{
  namespace
  {
    /** Lattice points per cell direction on which crossings are sought. */
    constexpr unsigned int n_sub_cells = 4;

    /**
     * Points of the zero level set in a cut cell: the crossings of the
     * edges of a sub-lattice, psi interpolated from the vertices (Q1). They
     * lie a quarter cell apart, so that the distance to them is within a
     * small fraction of a cell of the distance to the surface.
     */
    template <int dim>
    void
    add_crossings(
      const typename DoFHandler<dim>::active_cell_iterator           &cell,
      const std::array<double, GeometryInfo<dim>::vertices_per_cell> &values,
      std::vector<Point<dim>>                                        &crossings)
    {
      const Point<dim> lower = cell->vertex(0);
      const Point<dim> upper =
        cell->vertex(GeometryInfo<dim>::vertices_per_cell - 1);
      auto interpolate = [&](const Point<dim> &xi) {
        double value = 0;
        for (unsigned int v = 0; v < values.size(); ++v)
          {
            double weight = 1;
            for (unsigned int d = 0; d < dim; ++d)
              weight *= ((v >> d) & 1) ? xi[d] : 1 - xi[d];
            value += weight * values[v];
          }
        return value;
      };

      const unsigned int n        = n_sub_cells + 1;
      unsigned int       n_points = 1;
      for (unsigned int d = 0; d < dim; ++d)
        n_points *= n;
      for (unsigned int i = 0; i < n_points; ++i)
        {
          Point<dim>   xi;
          unsigned int rest = i;
          for (unsigned int d = 0; d < dim; ++d, rest /= n)
            xi[d] = double(rest % n) / n_sub_cells;
          const double a = interpolate(xi);
          for (unsigned int d = 0; d < dim; ++d)
            if (xi[d] < 1 - 1e-12)
              {
                Point<dim> next = xi;
                next[d] += 1. / n_sub_cells;
                const double b = interpolate(next);
                if ((a < 0) != (b < 0))
                  {
                    const Point<dim> zero = xi + a / (a - b) * (next - xi);
                    Point<dim>       x;
                    for (unsigned int e = 0; e < dim; ++e)
                      x[e] = lower[e] + zero[e] * (upper[e] - lower[e]);
                    crossings.push_back(x);
                  }
              }
        }
    }
  } // namespace

  template <int dim>
  void
  redistance(TransportedFields<dim> &fields)
  {
    constexpr unsigned int c   = TransportedFields<dim>::level_set_component;
    const auto            &psi = fields.fields;

    std::vector<Point<dim>> crossings;
    std::vector<bool>       keep(fields.owned_dofs.n_elements(), false);
    // Ghost cells too: an owned node may belong to a cut cell of another
    // rank only.
    for (const auto &cell : fields.dof_handler.active_cell_iterators())
      if (!cell->is_artificial())
        {
          std::array<double, GeometryInfo<dim>::vertices_per_cell> values;
          bool has_liquid = false, has_gas = false;
          for (const unsigned int v : cell->vertex_indices())
            {
              values[v] = psi(cell->vertex_dof_index(v, c));
              (values[v] < 0 ? has_liquid : has_gas) = true;
            }
          const bool cut = has_liquid && has_gas;
          if (cut && cell->is_locally_owned())
            add_crossings<dim>(cell, values, crossings);
          if (cut)
            for (const unsigned int v : cell->vertex_indices())
              {
                const auto dof = cell->vertex_dof_index(v, c);
                if (fields.owned_dofs.is_element(dof))
                  keep[fields.owned_dofs.index_within_set(dof)] = true;
              }
        }

    const MPI_Comm comm =
      fields.dof_handler.get_triangulation().get_communicator();
    std::vector<Point<dim>> all_crossings;
    for (const auto &part : Utilities::MPI::all_gather(comm, crossings))
      all_crossings.insert(all_crossings.end(), part.begin(), part.end());
    if (all_crossings.empty())
      return;

    const auto tree = pack_rtree(all_crossings);
    Point<dim> nearest;
    for (const auto &node : fields.nodes())
      {
        const auto dof = node.dofs[c];
        if (keep[fields.owned_dofs.index_within_set(dof)])
          continue;
        tree.query(boost::geometry::index::nearest(node.point, 1), &nearest);
        const double distance = node.point.distance(nearest);
        fields.fields(dof)    = psi(dof) < 0 ? -distance : distance;
      }
    fields.finalize();
  }

  template void
  redistance<2>(TransportedFields<2> &);
  template void
  redistance<3>(TransportedFields<3> &);
} // namespace vefs
