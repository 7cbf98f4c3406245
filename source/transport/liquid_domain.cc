#include <deal.II/base/bounding_box.h>
#include <deal.II/base/function.h>
#include <deal.II/base/qprojector.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/hp/q_collection.h>
#include <deal.II/non_matching/quadrature_generator.h>

#include <vefs/transport/liquid_domain.h>
#include <vefs/transport/midpoint_fallback.h>

#include <array>
#include <vector>

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

    /**
     * Cuts the cells of the mesh by the Q1 level set psi + shift w (w the
     * nodal weights sharp_liquid_volume() takes, 1 without them): where a
     * cell lies, and for a cut cell the quadratures of its liquid part and
     * surface on the reference cell.
     */
    template <int dim>
    class CellCutter
    {
      /**
       * How often the generator may split a cell before it falls back to
       * its midpoint rule, whose points are replaced by the sub-box's
       * corner estimate (midpoint_fallback.h). Twelve in 2D cost nothing
       * measurable; in 3D they took 1.9 times the run time, so deal.II's
       * four stay (doc/time_step_surface.md, step 4).
       */
      static constexpr unsigned int max_box_splits = dim == 2 ? 12 : 4;

      /** Sub-boxes per direction of a midpoint-fallback box. */
      static constexpr unsigned int n_fallback_subdivisions = 4;

    public:
      using Location = typename LiquidDomain<dim>::Location;

      CellCutter(const TransportedFields<dim>                      &fields,
                 const double                                       shift,
                 const typename TransportedFields<dim>::VectorType *weight)
        : fields(fields)
        , shift(shift)
        , weight(weight)
        , gauss_rule(QGauss<1>(LiquidDomain<dim>::n_gauss_points))
        , generator(gauss_rule,
                    NonMatching::AdditionalQGeneratorData(max_box_splits))
        , face_generator(gauss_rule)
      {
        for (unsigned int d = 0; d < dim; ++d)
          upper[d] = 1;
      }

      /** Where @p cell lies; a cut cell's quadratures follow from inside()
       * and surface() until the next call. */
      template <typename CellIterator>
      Location
      cut(const CellIterator &cell)
      {
        double lowest  = std::numeric_limits<double>::max();
        double highest = -lowest;
        for (const unsigned int v : cell->vertex_indices())
          {
            weights[v] =
              weight
                ? fields.entry_at(*weight,
                                  cell,
                                  v,
                                  TransportedFields<dim>::level_set_component)
                : 1.;
            values[v] = fields.level_set_at(cell, v) + shift * weights[v];
            lowest    = std::min(lowest, values[v]);
            highest   = std::max(highest, values[v]);
          }
        // A Q1 function takes its extremes at the vertices.
        if (!(lowest < 0))
          return Location::empty;
        if (highest <= 0)
          return Location::full;
        generator.generate(CellLevelSet<dim>(values),
                           BoundingBox<dim>(
                             std::make_pair(Point<dim>(), upper)));
        replace_midpoint_fallback();
        return Location::cut;
      }

      const Quadrature<dim> &
      inside() const
      {
        return patched ? patched_inside : generator.get_inside_quadrature();
      }

      /**
       * The derivative of inside_fraction() with respect to the shift that
       * the sub-boxes of the midpoint fallback contribute (the surface
       * quadrature lacks their piece of surface).
       */
      double
      fallback_derivative() const
      {
        return patched ? patched_derivative : 0.;
      }

      /** The liquid fraction of the cut cell: inside()'s weights. */
      double
      inside_fraction() const
      {
        double fraction = 0;
        for (const double w : inside().get_weights())
          fraction += w;
        return fraction;
      }

      const NonMatching::ImmersedSurfaceQuadrature<dim> &
      surface() const
      {
        return generator.get_surface_quadrature();
      }

      /**
       * The liquid part of face @p f of the cut cell: points on the face of
       * the reference cell, weights of the reference face.
       */
      Quadrature<dim>
      wet_face(const unsigned int f)
      {
        face_generator.generate(CellLevelSet<dim>(values),
                                BoundingBox<dim>(
                                  std::make_pair(Point<dim>(), upper)),
                                f);
        // The generator's face coordinates are deal.II's (in 3D (z, x) on
        // the faces normal to y), which QProjector maps into the cell.
        return QProjector<dim>::project_to_face(
          ReferenceCells::get_hypercube<dim>(),
          face_generator.get_inside_quadrature(),
          f);
      }

      /** The weight of the shift in the cut cell, for the quadratures'
       * points. */
      CellLevelSet<dim>
      shift_weight() const
      {
        return CellLevelSet<dim>(weights);
      }

      /** The mean of the cell's vertex weights. */
      double
      mean_shift_weight() const
      {
        double sum = 0;
        for (const double w : weights)
          sum += w;
        return sum / weights.size();
      }

      /** The cut cell's level set, for the quadratures' points. */
      CellLevelSet<dim>
      level_set() const
      {
        return CellLevelSet<dim>(values);
      }

    private:
      /**
       * Replace the generator's midpoint-fallback points, inside or outside,
       * by their boxes' corner quadratures (midpoint_fallback.h): the volume
       * stays continuous in the shift, so the volume correction can meet
       * its target.
       */
      void
      replace_midpoint_fallback()
      {
        // Most cut cells have none: they keep the generator's rules
        // without a copy (this runs for every cut cell of every volume
        // measurement).
        const auto has_fallback = [](const Quadrature<dim> &rule) {
          for (unsigned int q = 0; q < rule.size(); ++q)
            if (midpoint_fallback_box(rule.point(q),
                                      rule.weight(q),
                                      max_box_splits))
              return true;
          return false;
        };
        patched = false;
        if (!has_fallback(generator.get_inside_quadrature()) &&
            !has_fallback(generator.get_outside_quadrature()))
          return;
        std::vector<Point<dim>> points;
        std::vector<double>     weights;
        double                  derivative = 0;
        const CellLevelSet<dim> level_set(values);
        const auto              collect = [&](const Quadrature<dim> &rule,
                                 const bool             keep_others) {
          for (unsigned int q = 0; q < rule.size(); ++q)
            {
              const auto box = midpoint_fallback_box(rule.point(q),
                                                     rule.weight(q),
                                                     max_box_splits);
              if (box)
                {
                  patched = true;
                  append_corner_quadrature(level_set,
                                           *box,
                                           n_fallback_subdivisions,
                                           points,
                                           weights,
                                           derivative);
                }
              else if (keep_others)
                {
                  points.push_back(rule.point(q));
                  weights.push_back(rule.weight(q));
                }
            }
        };
        collect(generator.get_inside_quadrature(), true);
        collect(generator.get_outside_quadrature(), false);
        if (patched)
          {
            patched_inside     = Quadrature<dim>(points, weights);
            patched_derivative = derivative;
          }
      }

      const TransportedFields<dim>                      &fields;
      const double                                       shift;
      const typename TransportedFields<dim>::VectorType *weight;
      std::array<double, CellLevelSet<dim>::n_vertices>  weights;
      // The generator keeps a reference to its 1D rule.
      const hp::QCollection<1>                          gauss_rule;
      NonMatching::QuadratureGenerator<dim>             generator;
      NonMatching::FaceQuadratureGenerator<dim>         face_generator;
      Point<dim>                                        upper;
      std::array<double, CellLevelSet<dim>::n_vertices> values;
      bool                                              patched = false;
      Quadrature<dim>                                   patched_inside;
      double                                            patched_derivative = 0;
    };
  } // namespace

  template <int dim>
  LiquidDomain<dim>::LiquidDomain(const TransportedFields<dim> &fields)
    : fraction(fields.dof_handler.get_triangulation().n_active_cells())
    , locations(fraction.size(), Location::empty)
    , cut_index(fraction.size(), numbers::invalid_unsigned_int)
  {
    CellCutter<dim> cutter(fields, 0, nullptr);
    for (const auto &cell : fields.dof_handler.active_cell_iterators())
      if (!cell->is_artificial())
        {
          const unsigned int index = cell->active_cell_index();
          locations[index]         = cutter.cut(cell);
          if (locations[index] == Location::full)
            fraction[index] = 1;
          else if (locations[index] == Location::cut)
            {
              cut_index[index] = cut_cells.size();
              cut_cells.emplace_back();
              CutCell &cut_cell = cut_cells.back();
              cut_cell.inside   = cutter.inside();
              cut_cell.surface  = cutter.surface();
              // For what crosses open and velocity walls (outflow).
              if (cell->at_boundary())
                for (const unsigned int f : cell->face_indices())
                  if (cell->at_boundary(f))
                    cut_cell.wet_boundary_faces.emplace_back(f,
                                                             cutter.wet_face(
                                                               f));
              fraction[index] = cutter.inside_fraction();
            }
        }
  }

  template <int dim>
  SharpVolume
  sharp_liquid_volume(
    const TransportedFields<dim>                      &fields,
    const double                                       shift,
    const typename TransportedFields<dim>::VectorType *shift_weight)
  {
    using Location = typename LiquidDomain<dim>::Location;
    CellCutter<dim> cutter(fields, shift, shift_weight);
    SharpVolume     result;
    for (const auto &cell : fields.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const Location location = cutter.cut(cell);
          if (location == Location::full)
            result.volume += cell->measure();
          else if (location == Location::cut)
            {
              // On the reference cell dV/dshift = -int w/|grad psi| over
              // the surface; the box maps volumes by its measure. The
              // midpoint fallback's boxes (a saddle of psi, rare) take the
              // cell's mean weight: an estimate, which only slows Newton.
              double      derivative = 0;
              const auto  level_set  = cutter.level_set();
              const auto  weight     = cutter.shift_weight();
              const auto &surface    = cutter.surface();
              // Without weights (the default) w = 1: no interpolation.
              for (unsigned int q = 0; q < surface.size(); ++q)
                derivative -=
                  surface.weight(q) *
                  (shift_weight ? weight.value(surface.point(q)) : 1.) /
                  level_set.gradient(surface.point(q)).norm();
              derivative +=
                cutter.fallback_derivative() * cutter.mean_shift_weight();
              result.volume += cutter.inside_fraction() * cell->measure();
              result.derivative += derivative * cell->measure();
            }
        }
    const MPI_Comm comm =
      fields.dof_handler.get_triangulation().get_communicator();
    result.volume     = Utilities::MPI::sum(result.volume, comm);
    result.derivative = Utilities::MPI::sum(result.derivative, comm);
    return result;
  }

  template class LiquidDomain<2>;
  template class LiquidDomain<3>;
  template SharpVolume
  sharp_liquid_volume(const TransportedFields<2> &,
                      const double,
                      const TransportedFields<2>::VectorType *);
  template SharpVolume
  sharp_liquid_volume(const TransportedFields<3> &,
                      const double,
                      const TransportedFields<3>::VectorType *);
} // namespace vefs
