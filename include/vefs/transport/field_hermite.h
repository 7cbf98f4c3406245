#ifndef vefs_field_hermite_h
#define vefs_field_hermite_h

#include <vefs/fields/transported_fields.h>
#include <vefs/transport/level_set_gradient.h>

#include <array>

namespace vefs
{
  /**
   * Cubic Hermite interpolation of a transported field inside a cell, for
   * the values at the feet of the characteristics: the level set, and
   * optionally the flow fields. Linear interpolation there
   * loses O(h^2) per step, so the shape error grows like h^2/tau as the step
   * shrinks; the tensor-product cubic Hermite interpolant needs the nodal
   * derivatives d^|S| psi / prod_{d in S} dx_d, S a nonempty set of
   * directions (the gradient, the mixed second derivatives and, in 3D,
   * d^3/dxdydz).
   *
   * Two sources of the derivatives:
   * - recovered: all from the Q1 level set, averaging over the cells around a
   *   node the derivatives of the cells' Q1 interpolants (central
   *   differences on a uniform mesh): O(h^3) per step.
   * - gradient augmented (Nave, Rosales & Seibold, J. Comput. Phys. 229,
   *   2010): the gradient is the one carried along the characteristics
   *   (LevelSetGradient), the mixed derivatives are recovered from it the
   *   same way. The gradient holds what the nodal
   *   values alone cannot (a filament a few cells thin), so the
   *   interpolation stays accurate there.
   * The interpolant is continuous across cells.
   */
  template <int dim>
  class FieldHermite
  {
  public:
    /** Sets S are bit masks 1 .. 2^dim - 1; derivative S is stored at S-1. */
    static constexpr unsigned int n_derivatives = (1u << dim) - 1;

    /**
     * Make the nodal derivatives of the level set from the (ghosted) fields;
     * if @p advected_gradient is given, from that gradient.
     */
    void
    recover(const TransportedFields<dim> &fields,
            const LevelSetGradient<dim>  *advected_gradient = nullptr);

    /**
     * Also make the nodal derivatives of @p components (not the level set)
     * from their Q1 values, for component_value(); after recover(), whose
     * level set derivatives stay.
     */
    void
    recover_components(const TransportedFields<dim>    &fields,
                       const std::vector<unsigned int> &components);

    /**
     * The level set at the unit-cell point @p xi of @p cell (locally owned
     * or ghost; @p entries its TransportedFields::vertex_entries()), and its
     * gradient in @p gradient if not null. With
     * @p limited the value is clipped to the range of the cell's nodal
     * values, which keeps cubic overshoots out of kinks.
     */
    double
    value(const TransportedFields<dim>                         &fields,
          const typename DoFHandler<dim>::active_cell_iterator &cell,
          const typename TransportedFields<dim>::VertexEntries &entries,
          const Point<dim>                                     &xi,
          const bool                                            limited,
          Tensor<1, dim> *gradient = nullptr) const;

    /** Like value(), for a component of recover_components(). */
    double
    component_value(
      const TransportedFields<dim>                         &fields,
      const typename DoFHandler<dim>::active_cell_iterator &cell,
      const typename TransportedFields<dim>::VertexEntries &entries,
      const Point<dim>                                     &xi,
      const unsigned int                                    component,
      const bool                                            limited) const;

    /** The level set's nodal gradient at an owned @p node (after recover()). */
    Tensor<1, dim>
    nodal_gradient(const typename TransportedFields<dim>::Node &node) const
    {
      constexpr unsigned int c = TransportedFields<dim>::level_set_component;
      Tensor<1, dim>         gradient;
      for (unsigned int d = 0; d < dim; ++d)
        gradient[d] = derivatives[(1u << d) - 1](node.dofs[c]);
      return gradient;
    }

  private:
    double
    interpolate(const TransportedFields<dim>                         &fields,
                const typename DoFHandler<dim>::active_cell_iterator &cell,
                const typename TransportedFields<dim>::VertexEntries &entries,
                const Point<dim>                                     &xi,
                const unsigned int                                    component,
                const bool                                            limited,
                Tensor<1, dim> *gradient) const;

    std::array<typename TransportedFields<dim>::VectorType, n_derivatives>
      derivatives;
  };
} // namespace vefs

#endif
