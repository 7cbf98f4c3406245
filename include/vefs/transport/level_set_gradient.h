#ifndef vefs_level_set_gradient_h
#define vefs_level_set_gradient_h

#include <deal.II/base/function.h>

#include <vefs/fields/transported_fields.h>

namespace vefs
{
  /**
   * The gradient of the level set that the gradient-augmented transport
   * carries along the characteristics with it (doc/time_step_surface.md,
   * step 2): at each node, beside the level set value, the gradient
   * grad psi, moved by grad psi_new(x) = J^T grad psi_old(X(x)).
   * It is the nodal data of the cubic Hermite level set (FieldHermite).
   * The other transports leave it unread.
   *
   * Layout: that of the fields (TransportedFields::initialize_vector()), the
   * derivative in direction d in the slot of velocity component d; the
   * other slots are unused. Owned by the SurfaceTracker; it follows the
   * mesh with the fields (adapt_mesh()) and is saved in checkpoints.
   */
  template <int dim>
  class LevelSetGradient
  {
  public:
    using VectorType = typename TransportedFields<dim>::VectorType;
    using Node       = typename TransportedFields<dim>::Node;

    /** Zero on the layout of @p fields (after a mesh change). */
    void
    reinit(const TransportedFields<dim> &fields)
    {
      fields.initialize_vector(gradient);
    }

    /**
     * The gradient of @p level_set at every node of @p fields by central
     * differences (an expression has no analytic gradient).
     */
    void
    interpolate(const TransportedFields<dim> &fields,
                const Function<dim>          &level_set);

    /** At an owned node (TransportedFields::nodes()). */
    Tensor<1, dim>
    at(const Node &node) const
    {
      return TransportedFields<dim>::velocity_slots(gradient, node);
    }

    /** Writes the owned entry only: call finalize() after the last one. */
    void
    set(const Node &node, const Tensor<1, dim> &value)
    {
      TransportedFields<dim>::set_velocity_slots(gradient, node, value);
    }

    /**
     * At the vertex whose TransportedFields::vertex_entries() entry is
     * @p first (owned or ghost): the gradient has the fields' layout.
     */
    Tensor<1, dim>
    at_entry(const unsigned int first) const
    {
      Tensor<1, dim> value;
      for (unsigned int d = 0; d < dim; ++d)
        value[d] = gradient.local_element(first + d);
      return value;
    }

    /** Hanging nodes and ghost entries consistent after a change. */
    void
    finalize(const TransportedFields<dim> &fields)
    {
      fields.make_consistent(gradient);
    }

    /** @p copy: the gradient on the layout of @p fields, ghosts up to date. */
    void
    copy_to(VectorType &copy, const TransportedFields<dim> &fields) const
    {
      fields.initialize_vector(copy);
      copy.copy_locally_owned_data_from(gradient);
      copy.update_ghost_values();
    }

    /**
     * Exchange the vector with @p other, of the same layout: the level set
     * history lends its kept gradient for an interpolation, the mesh
     * change hands over the transferred one.
     */
    void
    swap(VectorType &other)
    {
      gradient.swap(other);
    }

    /** For the mesh transfer and the checkpoints. */
    const VectorType &
    vector() const
    {
      return gradient;
    }

    /** For the loading of a checkpoint and the unit tests. */
    VectorType &
    mutable_vector()
    {
      return gradient;
    }

  private:
    VectorType gradient;
  };
} // namespace vefs

#endif
