#ifndef vefs_flow_velocity_h
#define vefs_flow_velocity_h

#include <deal.II/base/timer.h>

#include <vefs/flow/flow_parameters.h>
#include <vefs/flow/stokes_step.h>
#include <vefs/stress/mechanical_energy.h>
#include <vefs/stress/rheology.h>
#include <vefs/transport/velocity_source.h>

namespace vefs
{
  /**
   * The velocity of a free-surface flow (doc/time_step_flow.md,
   * steps 7-9): the Stokes-like step on the liquid domain, solved again
   * while the contact set changes, then the copy of the new velocity to the
   * transported fields, the stress update and the extension of both beyond
   * the liquid for the next characteristics.
   */
  template <int dim>
  class FlowVelocity : public VelocitySource<dim>
  {
  public:
    /** @p flow: the Stokes step, also read by the visualization. */
    FlowVelocity(const FlowStepParameters &parameters,
                 const Rheology<dim>      &rheology,
                 StokesStep<dim>          &flow,
                 TimerOutput              &timer);

    std::string
    description() const override;

    void
    add_columns(StatisticsFile<dim> &statistics) const override;

    void
    set_initial_velocity(TransportedFields<dim> &fields) const override;

    void
    start(TransportedFields<dim>  &fields,
          const LiquidDomain<dim> &domain,
          const double             time,
          const bool               new_run) override;

    TimeStep
    time_step(const TimeControl            &time,
              const StepStatistics<dim>    &last,
              const TransportedFields<dim> &fields) const override;

    void
    set_advection_velocity(TransportedFields<dim> &fields,
                           const TimeControl      &time) override;

    void
    finish_advection(TransportedFields<dim> &fields,
                     const TimeControl      &time) override;

    void
    advance(TransportedFields<dim>  &fields,
            const LiquidDomain<dim> &domain,
            const TimeControl       &time,
            StepStatistics<dim>     &statistics) override;

    double
    outflow(const double tau) const override;

    void
    measure(StepStatistics<dim> &statistics) const override;

  private:
    /** What the solves of one step report. */
    struct SolveReport
    {
      /** Krylov iterations of all solves. */
      unsigned int iterations = 0;
      /** Whether the last update left the contact set unchanged. */
      bool contact_set_settled = true;
      /** Solves, one per contact iteration. */
      unsigned int solves = 0;
    };

    /**
     * Assemble the step of length @p tau on the set-up liquid domain and
     * solve it (solve_with_contact()).
     */
    SolveReport
    solve_step(const TransportedFields<dim> &fields, const double tau);

    /** Solve the assembled step, again while the contact set changes. */
    SolveReport
    solve_with_contact(const TransportedFields<dim> &fields, const double tau);

    /**
     * Copy the new velocity to @p fields, update the stress (or the
     * dumbbells, with the increments of @p step), and extend both beyond
     * the liquid, at least @p expected_cfl cells wide.
     */
    void
    update_fields(TransportedFields<dim>  &fields,
                  const LiquidDomain<dim> &domain,
                  const double             tau,
                  const double             expected_cfl,
                  const unsigned int       step,
                  StepStatistics<dim>     &statistics);

    /**
     * The second-order scheme's acceleration at the nodes flagged in
     * @p known: a = ((u - u*) / tau - (1 - w) a*) / w, the new forces over
     * rho (the momentum equation weighs them by w, about 1/2, beside the old
     * ones, rho a*: FlowStepParameters::new_force_weight), u the new
     * velocity in @p fields, u* and a* in @p advected.
     */
    void
    set_acceleration(
      TransportedFields<dim>                            &fields,
      const typename TransportedFields<dim>::VectorType &advected,
      const typename TransportedFields<dim>::VectorType &known,
      const double                                       tau) const;

    /**
     * The acceleration of a new run's initial state, which the second-order
     * scheme's first step needs: one flow solve over one 'Time/Time step'
     * from the initial velocity, which is kept.
     */
    void
    find_initial_acceleration(TransportedFields<dim> &fields);

    /**
     * Clear the flag in @p known of the nodes outside the liquid whose
     * velocity the extension gives ('Flow/Outside velocity of cut cells').
     */
    void
    unflag_extended_velocity_nodes(
      const TransportedFields<dim>                &fields,
      typename TransportedFields<dim>::VectorType &known) const;

    /** u + @p factor a at every node of @p fields. */
    void
    add_acceleration_to_velocity(TransportedFields<dim> &fields,
                                 const double            factor) const;

    /** The energies of @p fields on @p domain (the energy budget's). */
    MechanicalEnergy
    energy(const TransportedFields<dim> &fields,
           const LiquidDomain<dim>      &domain) const;

    /**
     * Whether the energy budget splits off the stress update's own share
     * (energy_change_stress_update): with a macroscopic stress, whose
     * update elastic_energy_of_pointwise_update() repeats at the
     * quadrature points.
     */
    bool
    budgets_stress_update() const;

    const FlowStepParameters parameters;
    const Rheology<dim>     &rheology;
    /**
     * Whether the fields' velocity is the second-order trace's, u + tau/2 a,
     * between set_advection_velocity() and finish_advection().
     */
    bool trace_velocity_in_fields = false;
    /** With the energy budget: the energy at the end of the last step. */
    double last_energy = 0;
    /**
     * The contact walls' reaction in the solve that found the initial
     * acceleration of a new run: the force at t = 0 for the first step's
     * mean (measure()).
     */
    double           initial_contact_reaction = 0;
    StokesStep<dim> &flow;
    TimerOutput     &timer;
    /** Solves per step with contact walls, at the most. */
    static constexpr unsigned int max_contact_iterations = 10;
  };
} // namespace vefs

#endif
