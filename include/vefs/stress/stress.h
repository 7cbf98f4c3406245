#ifndef vefs_stress_h
#define vefs_stress_h

#include <deal.II/lac/vector.h>

#include <vefs/fields/transported_fields.h>
#include <vefs/stress/rheology.h>
#include <vefs/transport/liquid_domain.h>

#include <functional>

namespace vefs
{
  /** What the stress update reports of the velocity gradient it used. */
  struct StressUpdateReport
  {
    /**
     * Largest |grad u| (Frobenius norm) at the nodes updated: tau times it
     * is the strain of one step, which the update resolves only if small.
     */
    double max_velocity_gradient = 0;
    /** Node values (per cell) whose strain the limiter scaled down. */
    unsigned int strain_limited_points = 0;
  };

  /**
   * The traceless part L - (tr L / d) I of the velocity gradient. The
   * liquid is incompressible, but the discrete velocity is not exactly
   * divergence free (stabilized equal-order elements, cut cells), and a
   * divergence that keeps its sign at one place, as at the corner of a
   * no-slip wall and the free surface, inflates c there by
   * exp(2 tau div u) every step: an isotropic stress, and elastic energy
   * from nowhere (2D beam: 4.5 -> 85 J/m while it lay at rest). Without
   * the trace the exponential update keeps det c exactly.
   */
  template <int dim>
  Tensor<2, dim>
  traceless(const Tensor<2, dim> &L)
  {
    return L - (trace(L) / dim) * unit_symmetric_tensor<dim>();
  }

  /**
   * Calls @p carry for each vertex of each locally owned liquid cell with
   * the traceless part L of the velocity gradient (of @p velocity, a vector
   * with the layout of the fields) by which that cell carries the stress of
   * the vertex: a full cell its Q1 gradient at the vertex, a cut cell at
   * all its vertices the mean gradient over its liquid part (the gradient
   * the flow step's stress term sees). Returns, over all ranks, the
   * largest velocity gradient met and how often @p rheology's strain
   * limiter acts on tau L. Collective.
   */
  template <int dim>
  StressUpdateReport
  for_each_liquid_vertex(
    const TransportedFields<dim>                      &fields,
    const typename TransportedFields<dim>::VectorType &velocity,
    const LiquidDomain<dim>                           &domain,
    const Rheology<dim>                               &rheology,
    const double                                       tau,
    const std::function<
      void(const typename DoFHandler<dim>::active_cell_iterator &cell,
           const unsigned int                                    v,
           const Tensor<2, dim>                                 &L)> &carry);

  /**
   * Step 9 of doc/time_step_flow.md: the new stress sigma^{n+1} at
   * the nodes of liquid cells, from the advected stress sigma* that @p fields
   * holds there and the new velocity (already copied into @p fields). Each
   * liquid cell carries the stress of its vertices by a velocity gradient:
   * a full cell by its Q1 gradient at the vertex, a cut cell at all its
   * vertices by the mean gradient over its liquid part (the gradient the
   * flow step's stress term sees). The nodal value is the cell-volume
   * weighted average of these, so that a liquid at rest keeps its stress
   * exactly; with NodalStress::lumped_increment, sigma* plus the lumped
   * increment of the update at the quadrature points of the liquid, unless
   * that leaves the conformation tensor less than half as positive as the
   * average does (stress.cc). A node outside the liquid may then carry at
   * most a bounded multiple of the stretch of its cells' liquid nodes
   * (stress.cc), unless @p outside_extended: the extension then overwrites
   * those nodes. Other nodes keep their values (the extension overwrites
   * them). The velocity gradient is taken from @p velocity, a vector with
   * the layout of the fields: the fields themselves, or theta u + (1 -
   * theta) u* for 'Stress theta' < 1. Returns the largest velocity gradient
   * it met and how often the strain limiter acted.
   */
  template <int dim>
  StressUpdateReport
  update_stress(TransportedFields<dim>                            &fields,
                const typename TransportedFields<dim>::VectorType &velocity,
                const LiquidDomain<dim>                           &domain,
                const Rheology<dim>                               &rheology,
                const double                                       tau,
                const bool        outside_extended,
                const NodalStress nodal_stress);

  /** What the statistics report of the stress. */
  struct StressMeasure
  {
    /** Rheology::elastic_energy_density() integrated over the liquid cells. */
    double elastic_energy = 0;
    /** Smallest eigenvalue of the conformation tensor c (or B). */
    double min_conformation_eigenvalue = 1;
    /** Quadrature points of liquid cells where c is not positive definite. */
    unsigned int non_positive_points = 0;
  };

  template <int dim>
  StressMeasure
  measure_stress(const TransportedFields<dim> &fields,
                 const LiquidDomain<dim>      &domain,
                 const Rheology<dim>          &rheology);

  /**
   * The elastic energy the liquid would hold if the stress were updated at
   * the quadrature points of its cells (the points where the flow step
   * integrates the stress it does work against) instead of at the nodes:
   * sigma* interpolated from the nodes that @p fields holds, L the
   * traceless Q1 gradient of @p velocity there, Rheology::updated_stress().
   * The elastic energy after update_stress() less this one is what the
   * nodal update itself adds to the energy (the energy budget's column
   * energy_change_stress_update, doc/bouncing_ball.md). Collective.
   */
  template <int dim>
  double
  elastic_energy_of_pointwise_update(
    const TransportedFields<dim>                      &fields,
    const typename TransportedFields<dim>::VectorType &velocity,
    const LiquidDomain<dim>                           &domain,
    const Rheology<dim>                               &rheology,
    const double                                       tau);
} // namespace vefs

#endif
