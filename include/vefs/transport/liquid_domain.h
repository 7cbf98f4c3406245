#ifndef vefs_liquid_domain_h
#define vefs_liquid_domain_h

#include <deal.II/base/quadrature.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/lac/vector.h>
#include <deal.II/non_matching/immersed_surface_quadrature.h>

#include <vefs/compat/box_q1_values.h>
#include <vefs/fields/transported_fields.h>

#include <utility>
#include <vector>

namespace vefs
{
  /**
   * The liquid as the flow step sees it on the current mesh: the region
   * psi < 0 of the Q1 level set, cut out of every cell the surface crosses
   * (doc/method.md, "The liquid": the sharp liquid domain). A cut
   * cell carries quadratures, on the reference cell, of its liquid part and of
   * the piece of free surface inside it, generated from the cell's own
   * level set by deal.II's NonMatching::QuadratureGenerator.
   */
  template <int dim>
  class LiquidDomain
  {
  public:
    using CellIterator = typename Triangulation<dim>::active_cell_iterator;

    /** Where a cell lies with respect to the liquid. */
    enum class Location
    {
      empty,
      cut,
      full
    };

    /**
     * The liquid part and the free surface of one cut cell, and the liquid
     * part of each of its faces at the cavity's boundary: points on the face
     * of the reference cell, weights of the reference face.
     */
    struct CutCell
    {
      Quadrature<dim>                             inside;
      NonMatching::ImmersedSurfaceQuadrature<dim> surface;
      /** (face number, its liquid part), for the boundary faces only. */
      std::vector<std::pair<unsigned int, Quadrature<dim>>> wet_boundary_faces;

      /** The liquid part of boundary face @p f. */
      const Quadrature<dim> &
      wet_boundary_face(const unsigned int f) const
      {
        for (const auto &[face, rule] : wet_boundary_faces)
          if (face == f)
            return rule;
        AssertThrow(false, ExcMessage("Not a face at the boundary."));
        return wet_boundary_faces.front().second;
      }
    };

    /** Classify the owned and ghost cells of the mesh of @p fields. */
    explicit LiquidDomain(const TransportedFields<dim> &fields);

    Location
    location(const CellIterator &cell) const
    {
      return locations[cell->active_cell_index()];
    }

    bool
    has_liquid(const CellIterator &cell) const
    {
      return location(cell) != Location::empty;
    }

    /** The quadratures of a cell whose location() is Location::cut. */
    const CutCell &
    cut_cell(const CellIterator &cell) const
    {
      return cut_cells[cut_index[cell->active_cell_index()]];
    }

    /** Liquid fraction of every owned and ghost cell (active cell index). */
    const Vector<float> &
    fractions() const
    {
      return fraction;
    }

    /** Points per direction of the Gauss rules the quadratures are made of. */
    static constexpr unsigned int n_gauss_points = 2;

  private:
    Vector<float>             fraction;
    std::vector<Location>     locations;
    std::vector<unsigned int> cut_index;
    std::vector<CutCell>      cut_cells;
  };

  /** Volume of the liquid psi + shift w < 0 and its derivative in the
   * shift. */
  struct SharpVolume
  {
    double volume     = 0;
    double derivative = 0;
  };

  /**
   * The liquid volume of a LiquidDomain built from the level set psi + shift
   * w (owned cells, summed over the ranks): the volume the flow step
   * integrates over. w is the level set entry of @p shift_weight (a vector
   * of the fields' layout, ghosts updated), 1 without it.
   */
  template <int dim>
  SharpVolume
  sharp_liquid_volume(
    const TransportedFields<dim>                      &fields,
    const double                                       shift,
    const typename TransportedFields<dim>::VectorType *shift_weight = nullptr);

  /**
   * Q1 shape functions on the liquid part of a cell: a Gauss rule on a full
   * cell, the cell's own rule on a cut one.
   */
  template <int dim>
  class LiquidValues
  {
  public:
    explicit LiquidValues(const LiquidDomain<dim> &domain)
      : domain(domain)
      , full_cell_rule(LiquidDomain<dim>::n_gauss_points)
    {
    }

    /** Values on the liquid part of @p cell, which must hold liquid. */
    template <typename CellIterator>
    const BoxCellValues<dim> &
    reinit(const CellIterator &cell)
    {
      values.reinit(cell,
                    domain.location(cell) == LiquidDomain<dim>::Location::cut
                      ? domain.cut_cell(cell).inside
                      : full_cell_rule);
      return values;
    }

  private:
    const LiquidDomain<dim> &domain;
    const QGauss<dim>        full_cell_rule;
    BoxCellValues<dim>       values;
  };
} // namespace vefs

#endif
