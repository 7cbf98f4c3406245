#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>

#include <vefs/free_surface.h>

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
                    update_values | update_quadrature_points |
                      update_JxW_values)
        , psi(fe_values.n_quadrature_points)
      {}

      /** Adds the cell's share to @p measure; returns the cell's volume of liquid. */
      double
      add(const typename DoFHandler<dim>::active_cell_iterator &cell,
          const double                                          shift,
          LiquidMeasure<dim> &                                  measure)
      {
        const double width = cell->minimum_vertex_distance() / n_sub_cells;
        double       lowest = std::numeric_limits<double>::max();
        double       highest = -lowest;
        for (const unsigned int v : cell->vertex_indices())
          {
            const double value =
              fields.fields(cell->vertex_dof_index(
                v, TransportedFields<dim>::level_set_component)) +
              shift;
            lowest  = std::min(lowest, value);
            highest = std::max(highest, value);
          }
        // Q1 fields take their extremes at vertices: most cells are
        // entirely liquid or entirely empty.
        if (lowest >= width)
          return 0;
        if (highest <= -width)
          {
            const double volume = cell->measure();
            measure.volume += volume;
            measure.first_moment += volume * cell->center();
            return volume;
          }

        fe_values.reinit(cell);
        fe_values[FEValuesExtractors::Scalar(
                    TransportedFields<dim>::level_set_component)]
          .get_function_values(fields.fields, psi);
        double liquid = 0;
        for (const unsigned int q : fe_values.quadrature_point_indices())
          {
            const double s  = -(psi[q] + shift) / width;
            const double dV = smooth_heaviside(s) * fe_values.JxW(q);
            liquid += dV;
            measure.first_moment += dV * fe_values.quadrature_point(q);
            measure.volume_derivative -=
              smooth_delta(s) / width * fe_values.JxW(q);
          }
        measure.volume += liquid;
        return liquid;
      }

    private:
      const TransportedFields<dim> &fields;
      FEValues<dim>                 fe_values;
      std::vector<double>           psi;
    };
  } // namespace

  template <int dim>
  LiquidMeasure<dim>
  measure_liquid(const TransportedFields<dim> &fields, const double shift)
  {
    LiquidMeasure<dim>  measure;
    CellIntegrator<dim> integrator(fields);
    for (const auto &cell : fields.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        integrator.add(cell, shift, measure);

    const MPI_Comm comm =
      fields.dof_handler.get_triangulation().get_communicator();
    measure.volume            = Utilities::MPI::sum(measure.volume, comm);
    measure.volume_derivative = Utilities::MPI::sum(measure.volume_derivative, comm);
    for (unsigned int d = 0; d < dim; ++d)
      measure.first_moment[d] = Utilities::MPI::sum(measure.first_moment[d], comm);
    return measure;
  }

  template <int dim>
  double
  correct_volume(TransportedFields<dim> &fields, const double target)
  {
    // Newton's method on the shift; the volume is smooth and monotone in it.
    double shift = 0;
    for (unsigned int iteration = 0; iteration < 20; ++iteration)
      {
        const auto   measure  = measure_liquid(fields, shift);
        const double residual = measure.volume - target;
        if (std::abs(residual) <= 1e-13 * target ||
            measure.volume_derivative == 0)
          break;
        shift -= residual / measure.volume_derivative;
      }

    for (const auto &node : fields.nodes())
      fields.fields(node.dofs[TransportedFields<dim>::level_set_component]) +=
        shift;
    fields.finalize();
    return shift;
  }

  template <int dim>
  Vector<float>
  liquid_fractions(const TransportedFields<dim> &fields)
  {
    Vector<float> fractions(
      fields.dof_handler.get_triangulation().n_active_cells());
    CellIntegrator<dim> integrator(fields);
    LiquidMeasure<dim>  unused;
    for (const auto &cell : fields.dof_handler.active_cell_iterators())
      if (!cell->is_artificial())
        fractions[cell->active_cell_index()] =
          integrator.add(cell, 0, unused) / cell->measure();
    return fractions;
  }

  template <int dim>
  double
  liquid_extent_on_wall(const TransportedFields<dim> &fields,
                        const types::boundary_id      boundary_id,
                        const unsigned int            coordinate,
                        const double                  value_if_dry)
  {
    constexpr unsigned int c       = TransportedFields<dim>::level_set_component;
    double                 extent  = -std::numeric_limits<double>::max();
    auto                   visit_edge = [&](const auto &edge) {
      const double     psi_a = fields.fields(edge->vertex_dof_index(0, c));
      const double     psi_b = fields.fields(edge->vertex_dof_index(1, c));
      const Point<dim> a     = edge->vertex(0);
      const Point<dim> b     = edge->vertex(1);
      if (psi_a <= 0)
        extent = std::max(extent, a[coordinate]);
      if (psi_b <= 0)
        extent = std::max(extent, b[coordinate]);
      if ((psi_a < 0) != (psi_b < 0))
        extent = std::max(
          extent, (a + psi_a / (psi_a - psi_b) * (b - a))[coordinate]);
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
      extent, fields.dof_handler.get_triangulation().get_communicator());
    return extent == -std::numeric_limits<double>::max() ? value_if_dry :
                                                           extent;
  }

#define VEFS_INSTANTIATE(dim)                                              \
  template LiquidMeasure<dim> measure_liquid(const TransportedFields<dim> &, \
                                             const double);                  \
  template double        correct_volume(TransportedFields<dim> &, const double); \
  template Vector<float> liquid_fractions(const TransportedFields<dim> &);   \
  template double        liquid_extent_on_wall(const TransportedFields<dim> &, \
                                        const types::boundary_id,          \
                                        const unsigned int,                \
                                        const double);
  VEFS_INSTANTIATE(2)
  VEFS_INSTANTIATE(3)
#undef VEFS_INSTANTIATE
} // namespace vefs
