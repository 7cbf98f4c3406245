#include <deal.II/base/bounding_box.h>
#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/hp/q_collection.h>
#include <deal.II/non_matching/quadrature_generator.h>

#include <vefs/liquid_domain.h>

#include <array>

namespace vefs
{
  namespace
  {
    /**
     * The Q1 level set of one cell on the reference cell [0,1]^dim, from its
     * vertex values (deal.II's lexicographic vertex order: bit d of the
     * vertex number is the d-th reference coordinate).
     */
    template <int dim>
    class CellLevelSet : public Function<dim>
    {
    public:
      static constexpr unsigned int n_vertices = 1u << dim;

      explicit CellLevelSet(const std::array<double, n_vertices> &values)
        : values(values)
      {
      }

      double
      value(const Point<dim> &xi, const unsigned int = 0) const override
      {
        double result = 0;
        for (unsigned int v = 0; v < n_vertices; ++v)
          result += values[v] * shape(v, xi, dim);
        return result;
      }

      Tensor<1, dim>
      gradient(const Point<dim> &xi, const unsigned int = 0) const override
      {
        Tensor<1, dim> result;
        for (unsigned int v = 0; v < n_vertices; ++v)
          for (unsigned int d = 0; d < dim; ++d)
            result[d] += values[v] * shape(v, xi, d);
        return result;
      }

      SymmetricTensor<2, dim>
      hessian(const Point<dim> &xi, const unsigned int = 0) const override
      {
        SymmetricTensor<2, dim> result;
        for (unsigned int v = 0; v < n_vertices; ++v)
          for (unsigned int d = 0; d < dim; ++d)
            for (unsigned int e = d + 1; e < dim; ++e)
              result[d][e] += values[v] * shape(v, xi, d, e);
        return result;
      }

    private:
      /**
       * The shape function of vertex @p v, differentiated in the reference
       * directions @p d and @p e (none if equal to dim).
       */
      static double
      shape(const unsigned int v,
            const Point<dim>  &xi,
            const unsigned int d,
            const unsigned int e = dim)
      {
        double result = 1;
        for (unsigned int c = 0; c < dim; ++c)
          {
            const bool upper = (v >> c) & 1;
            if (c == d || c == e)
              result *= upper ? 1. : -1.;
            else
              result *= upper ? xi[c] : 1. - xi[c];
          }
        return result;
      }

      const std::array<double, n_vertices> values;
    };
  } // namespace

  template <int dim>
  LiquidDomain<dim>::LiquidDomain(const TransportedFields<dim> &fields)
    : fraction(fields.dof_handler.get_triangulation().n_active_cells())
    , locations(fraction.size(), Location::empty)
    , cut_index(fraction.size(), numbers::invalid_unsigned_int)
  {
    const hp::QCollection<1>              gauss_rule{QGauss<1>(n_gauss_points)};
    NonMatching::QuadratureGenerator<dim> generator(gauss_rule);
    Point<dim>                            upper;
    for (unsigned int d = 0; d < dim; ++d)
      upper[d] = 1;
    const BoundingBox<dim> reference_cell(std::make_pair(Point<dim>(), upper));

    std::array<double, CellLevelSet<dim>::n_vertices> values;
    for (const auto &cell : fields.dof_handler.active_cell_iterators())
      if (!cell->is_artificial())
        {
          double lowest  = std::numeric_limits<double>::max();
          double highest = -lowest;
          for (const unsigned int v : cell->vertex_indices())
            {
              values[v] = fields.fields(cell->vertex_dof_index(
                v,
                TransportedFields<dim>::level_set_component));
              lowest    = std::min(lowest, values[v]);
              highest   = std::max(highest, values[v]);
            }
          // A Q1 function takes its extremes at the vertices.
          const unsigned int index = cell->active_cell_index();
          if (!(lowest < 0))
            continue;
          if (highest <= 0)
            {
              locations[index] = Location::full;
              fraction[index]  = 1;
              continue;
            }
          generator.generate(CellLevelSet<dim>(values), reference_cell);
          locations[index] = Location::cut;
          cut_index[index] = cut_cells.size();
          cut_cells.push_back({generator.get_inside_quadrature(),
                               generator.get_surface_quadrature()});
          double volume = 0;
          for (const double w : cut_cells.back().inside.get_weights())
            volume += w;
          fraction[index] = volume;
        }
  }

  template class LiquidDomain<2>;
  template class LiquidDomain<3>;
} // namespace vefs
