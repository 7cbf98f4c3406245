#ifndef vefs_box_q1_values_h
#define vefs_box_q1_values_h

#include <deal.II/base/geometry_info.h>
#include <deal.II/base/point.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/base/tensor.h>
#include <deal.II/grid/tria_accessor.h>
#include <deal.II/non_matching/immersed_surface_quadrature.h>

#include <array>
#include <utility>
#include <vector>

namespace vefs
{
  using namespace dealii;

  namespace internal
  {
    /**
     * The lengths of the edges of a box cell parallel to the axes, the
     * diagonal of its Jacobian.
     */
    template <int dim, typename CellIterator>
    Tensor<1, dim>
    box_extent(const CellIterator &cell)
    {
      // From two vertices (bit d of a vertex's index is its d-th
      // coordinate): extent_in_direction() measures four edges in 3D.
      Tensor<1, dim>    extent;
      const Point<dim> &lower = cell->vertex(0);
      for (unsigned int d = 0; d < dim; ++d)
        extent[d] = cell->vertex(1u << d)[d] - lower[d];
      return extent;
    }

    /**
     * The Q1 shape function of vertex @p v at @p xi on the reference cell
     * (deal.II's vertex order: bit d of v is the d-th coordinate), and with
     * @p derivative < dim its derivative in that reference direction.
     */
    template <int dim>
    double
    q1_shape(const unsigned int v,
             const Point<dim>  &xi,
             const unsigned int derivative = dim)
    {
      double result = 1;
      for (unsigned int d = 0; d < dim; ++d)
        {
          const bool upper = (v >> d) & 1;
          if (d == derivative)
            result *= upper ? 1. : -1.;
          else
            result *= upper ? xi[d] : 1. - xi[d];
        }
      return result;
    }
  } // namespace internal

  /**
   * The Q1 interpolation from a parent's vertices to its children's: by
   * child c and child vertex v, the non-zero weights (parent vertex w,
   * weight). Child c's vertex v sits at (bit d of c + bit d of v) / 2 in
   * direction d of the parent's reference cell (deal.II numbers the
   * children of an isotropic refinement as the vertices they hold).
   */
  template <int dim>
  using ChildVertexWeights =
    std::vector<std::vector<std::vector<std::pair<unsigned int, double>>>>;

  /**
   * The same from a cell's vertices to those of its descendants @p depth
   * levels finer, by the descendant's position in the cell's lattice of
   * 2^depth cells per direction (lexicographic, x fastest: for depth 1 the
   * child's number) and its vertex.
   */
  template <int dim>
  ChildVertexWeights<dim>
  make_descendant_vertex_weights(const unsigned int depth)
  {
    constexpr unsigned int n_vertices = GeometryInfo<dim>::vertices_per_cell;
    const unsigned int     n_per_direction = 1u << depth;
    unsigned int           n_positions     = 1;
    for (unsigned int d = 0; d < dim; ++d)
      n_positions *= n_per_direction;
    ChildVertexWeights<dim> weights(
      n_positions,
      std::vector<std::vector<std::pair<unsigned int, double>>>(n_vertices));
    for (unsigned int position = 0; position < n_positions; ++position)
      for (unsigned int v = 0; v < n_vertices; ++v)
        {
          Point<dim> xi;
          for (unsigned int d = 0, rest = position; d < dim;
               ++d, rest /= n_per_direction)
            xi[d] =
              static_cast<double>(rest % n_per_direction + ((v >> d) & 1)) /
              n_per_direction;
          for (unsigned int w = 0; w < n_vertices; ++w)
            if (const double weight = internal::q1_shape(w, xi); weight != 0)
              weights[position][v].emplace_back(w, weight);
        }
    return weights;
  }

  template <int dim>
  ChildVertexWeights<dim>
  make_child_vertex_weights()
  {
    return make_descendant_vertex_weights<dim>(1);
  }

  /**
   * The Q1 shape functions, their gradients and JxW at the points of a
   * quadrature on a cell, in closed form: the cells of the cavity mesh are
   * boxes parallel to the axes, whose mapping is x = lower corner +
   * diag(extent) xi (what MappingQ1 computes there). An FEValues gives the
   * same numbers but must be built anew for every cut cell, whose quadrature
   * is its own.
   */
  template <int dim>
  class BoxCellValues
  {
  public:
    static constexpr unsigned int n_vertices =
      GeometryInfo<dim>::vertices_per_cell;

    template <typename CellIterator>
    void
    reinit(const CellIterator &cell, const Quadrature<dim> &quadrature)
    {
      const unsigned int   n_q    = quadrature.size();
      const Tensor<1, dim> extent = internal::box_extent<dim>(cell);
      double               volume = 1;
      for (unsigned int d = 0; d < dim; ++d)
        volume *= extent[d];
      const Point<dim> lower = cell->vertex(0);
      shape.resize(n_q);
      gradient.resize(n_q);
      JxW.resize(n_q);
      point.resize(n_q);
      for (unsigned int q = 0; q < n_q; ++q)
        {
          const Point<dim> &xi = quadrature.point(q);
          JxW[q]               = quadrature.weight(q) * volume;
          point[q]             = lower;
          for (unsigned int d = 0; d < dim; ++d)
            point[q][d] += extent[d] * xi[d];
          for (unsigned int v = 0; v < n_vertices; ++v)
            {
              shape[q][v] = internal::q1_shape(v, xi);
              for (unsigned int d = 0; d < dim; ++d)
                gradient[q][v][d] = internal::q1_shape(v, xi, d) / extent[d];
            }
        }
    }

    unsigned int
    size() const
    {
      return JxW.size();
    }

    /** The value at point @p q of the Q1 field with these vertex values. */
    template <typename T>
    T
    value(const std::array<T, n_vertices> &vertex_values,
          const unsigned int               q) const
    {
      T result = shape[q][0] * vertex_values[0];
      for (unsigned int v = 1; v < n_vertices; ++v)
        result += shape[q][v] * vertex_values[v];
      return result;
    }

    /** Shape function of vertex v at point q: shape[q][v]. */
    std::vector<std::array<double, n_vertices>>         shape;
    std::vector<std::array<Tensor<1, dim>, n_vertices>> gradient;
    std::vector<double>                                 JxW;
    std::vector<Point<dim>>                             point;
  };

  /**
   * The same on the free-surface piece of a cut cell, with the unit normal
   * (an FEImmersedSurfaceValues in closed form).
   */
  template <int dim>
  class BoxSurfaceValues
  {
  public:
    static constexpr unsigned int n_vertices =
      GeometryInfo<dim>::vertices_per_cell;

    template <typename CellIterator>
    void
    reinit(const CellIterator                                &cell,
           const NonMatching::ImmersedSurfaceQuadrature<dim> &surface)
    {
      const unsigned int n_q = surface.size();
      shape.resize(n_q);
      normal.resize(n_q);
      JxW.resize(n_q);
      const Tensor<1, dim> extent = internal::box_extent<dim>(cell);
      double               volume = 1;
      for (unsigned int d = 0; d < dim; ++d)
        volume *= extent[d];
      for (unsigned int q = 0; q < n_q; ++q)
        {
          // Nanson's formula with J = diag(extent).
          for (unsigned int d = 0; d < dim; ++d)
            normal[q][d] = surface.normal_vector(q)[d] / extent[d];
          const double stretch = normal[q].norm();
          normal[q] /= stretch;
          JxW[q]               = surface.weight(q) * volume * stretch;
          const Point<dim> &xi = surface.point(q);
          for (unsigned int v = 0; v < n_vertices; ++v)
            shape[q][v] = internal::q1_shape(v, xi);
        }
    }

    unsigned int
    size() const
    {
      return JxW.size();
    }

    /** Q1 shape function of vertex v at point q: shape[q][v]. */
    std::vector<std::array<double, n_vertices>> shape;
    std::vector<Tensor<1, dim>>                 normal;
    std::vector<double>                         JxW;
  };
} // namespace vefs

#endif
