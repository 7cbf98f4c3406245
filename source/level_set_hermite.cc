#include <vefs/level_set_hermite.h>

#include <algorithm>

namespace vefs
{
  namespace
  {
    /** Edge lengths of the axis-aligned @p cell. */
    template <int dim>
    Tensor<1, dim>
    extents(const typename DoFHandler<dim>::active_cell_iterator &cell)
    {
      Tensor<1, dim> h;
      for (unsigned int d = 0; d < dim; ++d)
        h[d] = cell->vertex(1u << d)[d] - cell->vertex(0)[d];
      return h;
    }
  } // namespace

  template <int dim>
  void
  LevelSetHermite<dim>::recover(const TransportedFields<dim> &fields)
  {
    constexpr unsigned int c = TransportedFields<dim>::level_set_component;
    constexpr unsigned int n_vertices = GeometryInfo<dim>::vertices_per_cell;
    const auto            &psi        = fields.fields;

    typename TransportedFields<dim>::VectorType n_cells;
    fields.initialize_vector(n_cells);
    for (auto &derivative : derivatives)
      fields.initialize_vector(derivative);

    for (const auto &cell : fields.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          std::array<double, n_vertices>                  values;
          std::array<types::global_dof_index, n_vertices> dofs;
          for (const unsigned int v : cell->vertex_indices())
            {
              dofs[v]   = cell->vertex_dof_index(v, c);
              values[v] = psi(dofs[v]);
            }
          const Tensor<1, dim> h = extents<dim>(cell);
          for (const unsigned int v : cell->vertex_indices())
            {
              n_cells(dofs[v]) += 1;
              for (unsigned int s = 1; s <= n_derivatives; ++s)
                {
                  // The Q1 interpolant's derivative S at vertex v: a
                  // difference over the vertices that agree with v outside
                  // S.
                  double derivative = 0;
                  for (unsigned int w = 0; w < n_vertices; ++w)
                    if (((w ^ v) & ~s) == 0)
                      {
                        double sign = 1;
                        for (unsigned int d = 0; d < dim; ++d)
                          if ((s >> d) & 1)
                            sign *= ((w >> d) & 1) ? 1. / h[d] : -1. / h[d];
                        derivative += sign * values[w];
                      }
                  derivatives[s - 1](dofs[v]) += derivative;
                }
            }
        }

    n_cells.compress(VectorOperation::add);
    for (auto &derivative : derivatives)
      {
        derivative.compress(VectorOperation::add);
        for (unsigned int i = 0; i < derivative.locally_owned_size(); ++i)
          if (n_cells.local_element(i) > 0)
            derivative.local_element(i) /= n_cells.local_element(i);
        derivative.update_ghost_values();
      }
  }

  template <int dim>
  double
  LevelSetHermite<dim>::value(
    const TransportedFields<dim>                         &fields,
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    const Point<dim>                                     &xi,
    const bool                                            limited) const
  {
    constexpr unsigned int c = TransportedFields<dim>::level_set_component;
    const Tensor<1, dim>   h = extents<dim>(cell);

    // One-dimensional cubic Hermite basis in direction d: value functions
    // b0[d][side] and slope functions b1[d][side] of the vertex at xi_d =
    // side, the slopes scaled to physical derivatives.
    double b0[dim][2], b1[dim][2];
    for (unsigned int d = 0; d < dim; ++d)
      {
        const double t = xi[d];
        b0[d][0]       = 1 - t * t * (3 - 2 * t);
        b0[d][1]       = t * t * (3 - 2 * t);
        b1[d][0]       = h[d] * t * (1 - t) * (1 - t);
        b1[d][1]       = -h[d] * t * t * (1 - t);
      }

    double value = 0;
    double lower = std::numeric_limits<double>::max();
    double upper = std::numeric_limits<double>::lowest();
    for (const unsigned int v : cell->vertex_indices())
      {
        const auto   dof   = cell->vertex_dof_index(v, c);
        const double psi_v = fields.fields(dof);
        lower              = std::min(lower, psi_v);
        upper              = std::max(upper, psi_v);
        for (unsigned int s = 0; s <= n_derivatives; ++s)
          {
            double weight = 1;
            for (unsigned int d = 0; d < dim; ++d)
              weight *=
                ((s >> d) & 1) ? b1[d][(v >> d) & 1] : b0[d][(v >> d) & 1];
            value += weight * (s == 0 ? psi_v : derivatives[s - 1](dof));
          }
      }
    return limited ? std::clamp(value, lower, upper) : value;
  }

  template class LevelSetHermite<2>;
  template class LevelSetHermite<3>;
} // namespace vefs
