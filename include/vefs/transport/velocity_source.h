#ifndef vefs_velocity_source_h
#define vefs_velocity_source_h

#include <vefs/base/statistics.h>
#include <vefs/base/time_control.h>
#include <vefs/fields/transported_fields.h>
#include <vefs/transport/liquid_domain.h>

#include <string>

namespace vefs
{
  /**
   * Where the velocity of a step comes from: the flow step
   * (doc/time_step_flow.md, steps 7-9) or a velocity prescribed by the scene
   * (doc/method.md, "Transport-only mode"). The time loop asks it for the
   * length of the next step, for the velocity the characteristics trace
   * along, and for the new velocity on the new liquid domain.
   */
  template <int dim>
  class VelocitySource
  {
  public:
    virtual ~VelocitySource() = default;

    /** What is computed, for the banner of a run. */
    virtual std::string
    description() const = 0;

    /** Register the statistics columns of what this source computes. */
    virtual void
    add_columns(StatisticsFile<dim> &statistics) const = 0;

    /**
     * Give the initial @p fields of a new run this source's velocity at
     * time 0, if it is not the scene's initial velocity.
     */
    virtual void
    set_initial_velocity(TransportedFields<dim> &fields) const = 0;

    /**
     * Ready for the state @p fields at @p time on @p domain (before its
     * first row); @p new_run: not resumed from a checkpoint, whose fields
     * hold all this source needs.
     */
    virtual void
    start(TransportedFields<dim>  &fields,
          const LiquidDomain<dim> &domain,
          const double             time,
          const bool               new_run) = 0;

    /** The next step after the step @p last measured, from @p time. */
    virtual TimeStep
    time_step(const TimeControl            &time,
              const StepStatistics<dim>    &last,
              const TransportedFields<dim> &fields) const = 0;

    /**
     * Give @p fields the velocity the characteristics of the step under way
     * in @p time trace along. Called again after a mesh change before the
     * advection: the same velocity.
     */
    virtual void
    set_advection_velocity(TransportedFields<dim> &fields,
                           const TimeControl      &time) = 0;

    /**
     * After the advection: give @p fields the advected velocity u* of the
     * step (the old velocity at the feet), if the trace's was another.
     */
    virtual void
    finish_advection(TransportedFields<dim> &, const TimeControl &)
    {
    }

    /**
     * The velocity (and the stress) at the end of the step under way in
     * @p time on the new liquid @p domain, extended beyond the liquid for
     * the next characteristics; what it measures goes into @p statistics.
     * Throws SolverError if the step fails.
     */
    virtual void
    advance(TransportedFields<dim>  &fields,
            const LiquidDomain<dim> &domain,
            const TimeControl       &time,
            StepStatistics<dim>     &statistics) = 0;

    /** The volume that left the cavity through open walls in a step. */
    virtual double
    outflow(const double tau) const = 0;

    /** Put what this source measures of the state into @p statistics. */
    virtual void
    measure(StepStatistics<dim> &statistics) const = 0;
  };
} // namespace vefs

#endif
