#ifndef vefs_health_check_h
#define vefs_health_check_h

#include <vefs/base/cavity.h>
#include <vefs/base/statistics.h>
#include <vefs/base/time_control.h>
#include <vefs/fields/transported_fields.h>
#include <vefs/stress/rheology.h>

#include <string>

namespace vefs
{
  /** The bounds of the checks below: subsection "Health check". */
  struct HealthCheckParameters
  {
    void
    declare(dealii::ParameterHandler &prm);

    double max_volume_change = 0.2;
    double max_cfl           = 50;
    /**
     * Largest growth of the total energy over a step, as a fraction of the
     * energy above the lowest state, in a scene nothing supplies with
     * energy; 0: not checked.
     */
    double max_energy_growth = 0.01;
    /** Smallest controlled step, as a fraction of 'Time/Time step'. */
    double min_time_step_fraction = 1e-6;
  };

  /**
   * The checks done at every step (doc/reliability.md: a run never ends with
   * exit 0 and results that are not finite). Each returns what is wrong, naming
   * the quantity and the entries to change, or an empty string; all are
   * collective over the ranks of @p fields and agree on every rank.
   */

  /** Whether the level set, velocity and stress are finite everywhere. */
  template <int dim>
  bool
  fields_are_finite(const TransportedFields<dim> &fields);

  /**
   * Before a step of length @p tau: its CFL number, the step count, and
   * @p controlled_tau, the step that the CFL and strain bounds allow (before
   * the end time and output times shorten it). @p cfl is the step's CFL
   * number on the finest cells; the bound applies to the cells of the
   * velocity, 2^@p flow_level_offset times larger ('Flow/Flow cells'):
   * the semi-Lagrangian transport is stable at any CFL number, and a
   * blown-up velocity shows on its own cells.
   */
  std::string
  step_problem(const HealthCheckParameters &parameters,
               const TimeParameters        &time,
               const unsigned int           step,
               const double                 tau,
               const double                 controlled_tau,
               const double                 cfl,
               const double                 max_velocity,
               const unsigned int           flow_level_offset);

  /**
   * After a step: the fields, the volume, and @p non_finite_statistic, the
   * statistics column found not finite (StatisticsFile::non_finite_column()),
   * empty if none.
   */
  template <int dim>
  std::string
  state_problem(const HealthCheckParameters  &parameters,
                const TransportedFields<dim> &fields,
                const StepStatistics<dim>    &statistics,
                const std::string            &non_finite_statistic);

  /**
   * The largest elastic wave number c tau / h (elastic_wave_number) at which
   * the implicit step keeps the energy of an impact as at 1: measured on the
   * 2D stiff ball at 1, 10, 100 and 1000 (doc/reliability.md, "Stiff
   * solids").
   */
  constexpr double trusted_elastic_wave_number = 10;

  /**
   * The total energy (kinetic + potential + elastic) of a solid or an
   * Oldroyd-B liquid in a scene that nothing supplies with energy, from
   * step to step: no equation of vefs creates
   * energy, so a step that adds much of it is the scheme's failure (an
   * elastic wave that crosses many cells per step, doc/reliability.md).
   * The growth of a step is measured against the energy above the lowest
   * state: the kinetic and elastic energies and the potential energy above
   * that of all the liquid in the lowest corner of the cavity. Only steps
   * beyond the trusted elastic wave number are judged: below it, a growth
   * has other causes that a step bound cannot tell from a trusted run (the
   * 3D soft ball's thin sheet gains 9 % of its energy in one step at
   * c tau / h = 0.1, doc/bouncing_ball.md).
   */
  class EnergyWatch
  {
  public:
    /**
     * @p active: whether to watch: a material with a stress in a scene
     * without a source of energy.
     */
    EnergyWatch(const bool                active,
                const MaterialParameters &material,
                const CavityParameters   &cavity);

    /** After the step measured in @p s: what is wrong, or "". */
    template <int dim>
    std::string
    problem(const HealthCheckParameters &parameters,
            const StepStatistics<dim>   &s);

  private:
    const bool   active;
    const double density;
    /** The largest g . x over the corners of the cavity. */
    double lowest_corner_height = 0;
    bool   has_previous         = false;
    double previous_total       = 0;
    double previous_scale       = 0;
  };
} // namespace vefs

#endif
