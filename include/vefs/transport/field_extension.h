#ifndef vefs_field_extension_h
#define vefs_field_extension_h

#include <vefs/fields/transported_fields.h>

#include <functional>
#include <vector>

namespace vefs
{
  /**
   * Extend the @p components of @p fields (flow_components(): the velocity,
   * and the stress if there is one) from the nodes flagged in
   * @p known (the nodes of liquid cells, flag = 1 in the first component of
   * the node) into @p n_layers layers of cells around the liquid: each layer
   * gives an unknown node the average of the known nodes of the cells it
   * shares with them. The characteristics of the next step trace back
   * through this band; farther nodes get zero. @p known comes back with the
   * extended nodes flagged too.
   */
  template <int dim>
  void
  extend_flow_fields(TransportedFields<dim>                      &fields,
                     typename TransportedFields<dim>::VectorType &known,
                     const unsigned int                           n_layers,
                     const std::vector<unsigned int>             &components);

  /** All components of @p fields but the level set. */
  template <int dim>
  std::vector<unsigned int>
  flow_components(const TransportedFields<dim> &fields);

  /** The velocity components. */
  template <int dim>
  std::vector<unsigned int>
  velocity_components();

  /** The acceleration components of @p fields (none without one). */
  template <int dim>
  std::vector<unsigned int>
  acceleration_components(const TransportedFields<dim> &fields);

  /**
   * The velocity components and the acceleration's (if @p fields carry
   * one): the acceleration is extended like the velocity.
   */
  template <int dim>
  std::vector<unsigned int>
  velocity_and_acceleration_components(const TransportedFields<dim> &fields);

  /**
   * The stress components of @p fields (none without a stress), and the
   * dumbbells' fields if any.
   */
  template <int dim>
  std::vector<unsigned int>
  stress_components(const TransportedFields<dim> &fields);

  /** Clear the flag in @p known of the owned nodes outside the liquid. */
  template <int dim>
  void
  unflag_nodes_outside_liquid(
    const TransportedFields<dim>                &fields,
    typename TransportedFields<dim>::VectorType &known);

  /**
   * Clear the flag in @p known of the owned nodes outside the liquid whose
   * point @p selected accepts.
   */
  template <int dim>
  void
  unflag_nodes_outside_liquid(
    const TransportedFields<dim>                          &fields,
    typename TransportedFields<dim>::VectorType           &known,
    const std::function<bool(const dealii::Point<dim> &)> &selected);
} // namespace vefs

#endif
