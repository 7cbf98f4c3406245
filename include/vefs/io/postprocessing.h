#ifndef vefs_postprocessing_h
#define vefs_postprocessing_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/vector.h>

#include <vefs/base/cavity.h>
#include <vefs/base/statistics.h>
#include <vefs/compat/box_mesh_locator.h>
#include <vefs/fields/transported_fields.h>
#include <vefs/stress/rheology.h>
#include <vefs/transport/liquid_domain.h>

namespace vefs
{
  /** What is measured beyond the statistics of every scene: subsection
   * "Postprocess". */
  struct PostprocessParameters
  {
    void
    declare(dealii::ParameterHandler &prm);

    /** Throws InputError for a probe point that is not in the cavity. */
    void
    check(const unsigned int dimension, const CavityParameters &cavity) const;

    /** Empty: no probe. */
    std::vector<double> probe_point = {};
    /** The energy changes of each stage of a step in the statistics. */
    bool energy_budget = false;
  };

  /** What a probe point sees. */
  template <int dim>
  struct Probe
  {
    /** The velocity field there (outside the liquid: its extension). */
    Tensor<1, dim> velocity;
    /** Whether the level set puts the point in the liquid. */
    bool in_liquid;
    /** The stress there, if the fields carry one. */
    SymmetricTensor<2, dim> stress;
    /**
     * With dumbbells: the standard error of the ensemble stress, per
     * component: G s / sqrt(N_f), s the standard deviation over the fields
     * of q_a q_b (Q1 in the cell like the stress).
     */
    SymmetricTensor<2, dim> stress_error;
  };

  /**
   * The velocity, the level set and the stress (if any) of @p fields at
   * @p point, on every rank; @p shear_modulus: G, for the dumbbells'
   * standard error.
   */
  template <int dim>
  Probe<dim>
  probe_velocity(const TransportedFields<dim> &fields,
                 const BoxMeshLocator<dim>    &locator,
                 const Point<dim>             &point,
                 const double                  shear_modulus);

  /**
   * Measure the liquid domain of the flow step: volume, centroid, energies
   * and the largest speed, and the extents of the liquid along
   * the floor and up the x- wall (the broken-dam front and residual height).
   */
  template <int dim>
  void
  measure_step(const MaterialParameters     &material,
               const CavityParameters       &cavity,
               const TransportedFields<dim> &fields,
               const LiquidDomain<dim>      &domain,
               const double                  initial_volume,
               const double                  expected_volume,
               StepStatistics<dim>          &statistics);

} // namespace vefs

#endif
