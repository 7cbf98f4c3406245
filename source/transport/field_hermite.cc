#include <vefs/transport/field_hermite.h>

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

    /**
     * Derivative S (a bit mask of directions) at vertex @p v of the Q1
     * interpolant of the vertex @p values of a cell with edges @p h: a
     * difference over the vertices that agree with v outside S.
     */
    template <int dim>
    double
    q1_derivative(const std::array<double, 1u << dim> &values,
                  const Tensor<1, dim>                &h,
                  const unsigned int                   v,
                  const unsigned int                   s)
    {
      double derivative = 0;
      for (unsigned int w = 0; w < values.size(); ++w)
        if (((w ^ v) & ~s) == 0)
          {
            double factor = 1;
            for (unsigned int d = 0; d < dim; ++d)
              if ((s >> d) & 1)
                factor *= ((w >> d) & 1) ? 1. / h[d] : -1. / h[d];
            derivative += factor * values[w];
          }
      return derivative;
    }
    /**
     * The sums of the cells' contributions in @p sums, divided by the number
     * of cells around each node (@p n_cells, summed the same way), ghosted.
     * Entries without a contribution keep their values.
     */
    template <std::size_t n>
    void
    mean_over_cells(
      std::array<LinearAlgebra::distributed::Vector<double>, n> &sums,
      LinearAlgebra::distributed::Vector<double>                &n_cells)
    {
      n_cells.compress(VectorOperation::add);
      for (auto &sum : sums)
        {
          sum.compress(VectorOperation::add);
          for (unsigned int i = 0; i < sum.locally_owned_size(); ++i)
            if (n_cells.local_element(i) > 0)
              sum.local_element(i) /= n_cells.local_element(i);
          sum.update_ghost_values();
        }
    }
  } // namespace

  template <int dim>
  void
  FieldHermite<dim>::recover(const TransportedFields<dim> &fields,
                             const LevelSetGradient<dim>  *advected_gradient)
  {
    constexpr unsigned int c = TransportedFields<dim>::level_set_component;
    constexpr unsigned int n_vertices = GeometryInfo<dim>::vertices_per_cell;

    typename TransportedFields<dim>::VectorType n_cells;
    fields.initialize_vector(n_cells);
    for (auto &derivative : derivatives)
      fields.initialize_vector(derivative);

    for (const auto &cell : fields.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          // values[0]: psi, values[1 + d]: its advected derivative in
          // direction d.
          std::array<std::array<double, n_vertices>, dim + 1> values;
          const auto entries = fields.vertex_entries(cell);
          for (const unsigned int v : cell->vertex_indices())
            {
              values[0][v] = fields.local_value(entries[v] + c);
              if (advected_gradient)
                {
                  const Tensor<1, dim> gradient =
                    advected_gradient->at_entry(entries[v]);
                  for (unsigned int d = 0; d < dim; ++d)
                    values[1 + d][v] = gradient[d];
                }
            }
          const Tensor<1, dim> h = extents<dim>(cell);
          for (const unsigned int v : cell->vertex_indices())
            {
              n_cells.local_element(entries[v] + c) += 1;
              for (unsigned int s = 1; s <= n_derivatives; ++s)
                {
                  double derivative = 0;
                  if (!advected_gradient)
                    derivative = q1_derivative<dim>(values[0], h, v, s);
                  else
                    {
                      // Mean over the directions d of S of the derivative
                      // S - {d} of the gradient component d.
                      unsigned int n_terms = 0;
                      for (unsigned int d = 0; d < dim; ++d)
                        if ((s >> d) & 1)
                          {
                            const unsigned int rest = s & ~(1u << d);
                            derivative +=
                              rest == 0
                                ? values[1 + d][v]
                                : q1_derivative<dim>(values[1 + d], h, v, rest);
                            ++n_terms;
                          }
                      derivative /= n_terms;
                    }
                  derivatives[s - 1].local_element(entries[v] + c) +=
                    derivative;
                }
            }
        }

    mean_over_cells(derivatives, n_cells);
  }

  template <int dim>
  void
  FieldHermite<dim>::recover_components(
    const TransportedFields<dim>    &fields,
    const std::vector<unsigned int> &components)
  {
    constexpr unsigned int n_vertices = GeometryInfo<dim>::vertices_per_cell;
    typename TransportedFields<dim>::VectorType n_cells;
    fields.initialize_vector(n_cells);
    // Only this function's sums may travel in compress(): the ghost entries
    // (the level set's derivatives, if recovered) are zeroed first.
    for (auto &derivative : derivatives)
      if (derivative.size() == 0)
        fields.initialize_vector(derivative);
      else
        derivative.zero_out_ghost_values();

    for (const auto &cell : fields.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const Tensor<1, dim> h       = extents<dim>(cell);
          const auto           entries = fields.vertex_entries(cell);
          for (const unsigned int c : components)
            {
              std::array<double, n_vertices> values;
              for (const unsigned int v : cell->vertex_indices())
                values[v] = fields.local_value(entries[v] + c);
              for (const unsigned int v : cell->vertex_indices())
                {
                  n_cells.local_element(entries[v] + c) += 1;
                  for (unsigned int s = 1; s <= n_derivatives; ++s)
                    derivatives[s - 1].local_element(entries[v] + c) +=
                      q1_derivative<dim>(values, h, v, s);
                }
            }
        }

    mean_over_cells(derivatives, n_cells);
  }

  template <int dim>
  double
  FieldHermite<dim>::value(
    const TransportedFields<dim>                         &fields,
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    const typename TransportedFields<dim>::VertexEntries &entries,
    const Point<dim>                                     &xi,
    const bool                                            limited,
    Tensor<1, dim>                                       *gradient) const
  {
    return interpolate(fields,
                       cell,
                       entries,
                       xi,
                       TransportedFields<dim>::level_set_component,
                       limited,
                       gradient);
  }

  template <int dim>
  double
  FieldHermite<dim>::component_value(
    const TransportedFields<dim>                         &fields,
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    const typename TransportedFields<dim>::VertexEntries &entries,
    const Point<dim>                                     &xi,
    const unsigned int                                    component,
    const bool                                            limited) const
  {
    return interpolate(fields, cell, entries, xi, component, limited, nullptr);
  }

  template <int dim>
  double
  FieldHermite<dim>::interpolate(
    const TransportedFields<dim>                         &fields,
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    const typename TransportedFields<dim>::VertexEntries &entries,
    const Point<dim>                                     &xi,
    const unsigned int                                    c,
    const bool                                            limited,
    Tensor<1, dim>                                       *gradient) const
  {
    const Tensor<1, dim> h = extents<dim>(cell);

    // One-dimensional cubic Hermite basis in direction d: basis[d][k][side]
    // with k = 0 the value function and k = 1 the slope function (scaled to
    // a physical derivative) of the vertex at xi_d = side; slopes[d][k][side]
    // their x_d-derivatives.
    double basis[dim][2][2], slopes[dim][2][2];
    for (unsigned int d = 0; d < dim; ++d)
      {
        const double t  = xi[d];
        basis[d][0][0]  = 1 - t * t * (3 - 2 * t);
        basis[d][0][1]  = t * t * (3 - 2 * t);
        basis[d][1][0]  = h[d] * t * (1 - t) * (1 - t);
        basis[d][1][1]  = -h[d] * t * t * (1 - t);
        slopes[d][0][0] = -6 * t * (1 - t) / h[d];
        slopes[d][0][1] = 6 * t * (1 - t) / h[d];
        slopes[d][1][0] = (1 - t) * (1 - 3 * t);
        slopes[d][1][1] = -t * (2 - 3 * t);
      }

    // The fields and the derivatives share one partitioner, whose local
    // indices the entries are. The weight of mode s at vertex v
    // is a product of one factor per direction; its x_e-derivative replaces
    // factor e by its slope (the products before and after e, kept as prefix
    // and suffix products).
    double value = 0;
    double lower = std::numeric_limits<double>::max();
    double upper = std::numeric_limits<double>::lowest();
    if (gradient)
      *gradient = Tensor<1, dim>();
    for (const unsigned int v : cell->vertex_indices())
      {
        const unsigned int local = entries[v] + c;
        const double       f_v   = fields.local_value(local);
        lower                    = std::min(lower, f_v);
        upper                    = std::max(upper, f_v);
        for (unsigned int s = 0; s <= n_derivatives; ++s)
          {
            const double nodal =
              s == 0 ? f_v : derivatives[s - 1].local_element(local);
            double factor[dim], slope[dim];
            for (unsigned int d = 0; d < dim; ++d)
              {
                factor[d] = basis[d][(s >> d) & 1][(v >> d) & 1];
                slope[d]  = slopes[d][(s >> d) & 1][(v >> d) & 1];
              }
            double before[dim + 1];
            before[0] = 1;
            for (unsigned int d = 0; d < dim; ++d)
              before[d + 1] = before[d] * factor[d];
            value += before[dim] * nodal;
            if (gradient)
              {
                double after = nodal;
                for (unsigned int e = dim; e-- > 0;)
                  {
                    (*gradient)[e] += before[e] * slope[e] * after;
                    after *= factor[e];
                  }
              }
          }
      }
    return limited ? std::clamp(value, lower, upper) : value;
  }

  template class FieldHermite<2>;
  template class FieldHermite<3>;
} // namespace vefs
