#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <vefs/transport/free_surface.h>

#include <cmath>
#include <limits>

namespace vefs
{
  namespace
  {
    /** Sub-cells per direction of the rule that integrates phi. */
    constexpr unsigned int n_sub_cells = 4;

    /** Heaviside of s smoothed over |s| < 1, and its derivative. */
    double
    smooth_heaviside(const double s)
    {
      if (s <= -1)
        return 0;
      if (s >= 1)
        return 1;
      return 0.5 * (1 + s + std::sin(numbers::PI * s) / numbers::PI);
    }

    double
    smooth_delta(const double s)
    {
      if (std::abs(s) >= 1)
        return 0;
      return 0.5 * (1 + std::cos(numbers::PI * s));
    }

    /** Integrates phi on one cell at a time. */
    template <int dim>
    class CellIntegrator
    {
    public:
      explicit CellIntegrator(const TransportedFields<dim> &fields)
        : fields(fields)
        , fe_values(fields.mapping,
                    fields.fe,
                    QIterated<dim>(QMidpoint<1>(), n_sub_cells),
                    update_values | update_gradients |
                      update_quadrature_points | update_JxW_values)
        , psi(fe_values.n_quadrature_points)
        , grad_psi(fe_values.n_quadrature_points)
      {
      }

      /** Adds the cell's free-surface area to @p surface_area; returns the
       * cell's volume of liquid. */
      double
      add(const typename DoFHandler<dim>::active_cell_iterator &cell,
          double                                               &surface_area)
      {
        const double width   = cell->minimum_vertex_distance() / n_sub_cells;
        double       lowest  = std::numeric_limits<double>::max();
        double       highest = -lowest;
        for (const unsigned int v : cell->vertex_indices())
          {
            const double value = fields.level_set_at(cell, v);
            lowest             = std::min(lowest, value);
            highest            = std::max(highest, value);
          }
        // Q1 fields take their extremes at vertices: most cells are
        // entirely liquid or entirely empty.
        if (lowest >= width)
          return 0;
        if (highest <= -width)
          return cell->measure();

        fe_values.reinit(cell);
        const FEValuesExtractors::Scalar level_set(
          TransportedFields<dim>::level_set_component);
        fe_values[level_set].get_function_values(fields.vector(), psi);
        fe_values[level_set].get_function_gradients(fields.vector(), grad_psi);
        double liquid = 0;
        for (const unsigned int q : fe_values.quadrature_point_indices())
          {
            const double s = -psi[q] / width;
            liquid += smooth_heaviside(s) * fe_values.JxW(q);
            const double delta = smooth_delta(s) / width * fe_values.JxW(q);
            surface_area += delta * grad_psi[q].norm();
          }
        return liquid;
      }

    private:
      const TransportedFields<dim> &fields;
      FEValues<dim>                 fe_values;
      std::vector<double>           psi;
      std::vector<Tensor<1, dim>>   grad_psi;
    };
  } // namespace

  template <int dim>
  double
  shape_error(const TransportedFields<dim> &fields,
              const Function<dim>          &exact_level_set)
  {
    constexpr unsigned int c = TransportedFields<dim>::level_set_component;
    const QIterated<dim>   rule(QMidpoint<1>(), 8);
    FEValues<dim>          fe_values(fields.mapping,
                            fields.fe,
                            rule,
                            update_values | update_quadrature_points |
                              update_JxW_values);
    std::vector<double>    psi(rule.size());
    double                 error = 0;
    for (const auto &cell : fields.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          // Both indicators are constant on the cell when psi keeps its sign
          // at the vertices (Q1) and the exact surface is farther than half
          // a diameter from the center.
          const double exact_center = exact_level_set.value(cell->center());
          bool uniform = std::abs(exact_center) > 0.51 * cell->diameter();
          for (const unsigned int v : cell->vertex_indices())
            uniform = uniform && ((fields.level_set_at(cell, v) < 0) ==
                                  (exact_center < 0));
          if (uniform)
            continue;
          fe_values.reinit(cell);
          fe_values[FEValuesExtractors::Scalar(c)]
            .get_function_values(fields.vector(), psi);
          for (const unsigned int q : fe_values.quadrature_point_indices())
            if ((psi[q] < 0) !=
                (exact_level_set.value(fe_values.quadrature_point(q)) < 0))
              error += fe_values.JxW(q);
        }
    return Utilities::MPI::sum(
      error,
      fields.dof_handler.get_triangulation().get_communicator());
  }

  template <int dim>
  double
  interface_thickness(const TransportedFields<dim> &fields,
                      const double                  finest_cell_size)
  {
    CellIntegrator<dim> integrator(fields);
    double              surface_area = 0, mixed_volume = 0;
    for (const auto &cell : fields.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const float fraction =
            integrator.add(cell, surface_area) / cell->measure();
          if (fraction > 0.01f && fraction < 0.99f)
            mixed_volume += cell->measure();
        }
    const MPI_Comm comm =
      fields.dof_handler.get_triangulation().get_communicator();
    mixed_volume = Utilities::MPI::sum(mixed_volume, comm);
    surface_area = Utilities::MPI::sum(surface_area, comm);
    return mixed_volume / surface_area / finest_cell_size;
  }

  template <int dim>
  double
  liquid_extent_on_wall(const TransportedFields<dim> &fields,
                        const types::boundary_id      boundary_id,
                        const unsigned int            coordinate,
                        const double                  value_if_dry)
  {
    double extent     = -std::numeric_limits<double>::max();
    auto   visit_edge = [&](const auto &edge) {
      const double     psi_a = fields.level_set_at(edge, 0);
      const double     psi_b = fields.level_set_at(edge, 1);
      const Point<dim> a     = edge->vertex(0);
      const Point<dim> b     = edge->vertex(1);
      if (psi_a <= 0)
        extent = std::max(extent, a[coordinate]);
      if (psi_b <= 0)
        extent = std::max(extent, b[coordinate]);
      if ((psi_a < 0) != (psi_b < 0))
        extent =
          std::max(extent, (a + psi_a / (psi_a - psi_b) * (b - a))[coordinate]);
    };

    for (const auto &cell : fields.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && cell->at_boundary())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary() && face->boundary_id() == boundary_id)
            {
              if constexpr (dim == 2)
                visit_edge(face);
              else
                for (unsigned int l = 0; l < face->n_lines(); ++l)
                  visit_edge(face->line(l));
            }

    extent = Utilities::MPI::max(
      extent,
      fields.dof_handler.get_triangulation().get_communicator());
    return extent == -std::numeric_limits<double>::max() ? value_if_dry
                                                         : extent;
  }

#define VEFS_INSTANTIATE(dim)                                           \
  template double shape_error(const TransportedFields<dim> &,           \
                              const Function<dim> &);                   \
  template double interface_thickness(const TransportedFields<dim> &,   \
                                      const double);                    \
  template double liquid_extent_on_wall(const TransportedFields<dim> &, \
                                        const types::boundary_id,       \
                                        const unsigned int,             \
                                        const double);
  VEFS_INSTANTIATE(2)
  VEFS_INSTANTIATE(3)
#undef VEFS_INSTANTIATE
} // namespace vefs
