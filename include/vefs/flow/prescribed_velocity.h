#ifndef vefs_prescribed_velocity_h
#define vefs_prescribed_velocity_h

#include <deal.II/base/function.h>

#include <vefs/transport/velocity_source.h>

#include <memory>
#include <string>

namespace vefs
{
  /**
   * A velocity given by the scene ('Prescribed velocity'), for transport
   * without a flow (doc/method.md, "Transport-only mode"): the
   * characteristics trace it at mid-step, which keeps the trace of a
   * time-dependent velocity second order, and the fields take it at the end
   * of each step.
   */
  template <int dim>
  class PrescribedVelocity : public VelocitySource<dim>
  {
  public:
    /** @p expression: 'Transport/Prescribed velocity'. */
    explicit PrescribedVelocity(const std::string &expression);

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
    advance(TransportedFields<dim>  &fields,
            const LiquidDomain<dim> &domain,
            const TimeControl       &time,
            StepStatistics<dim>     &statistics) override;

    double
    outflow(const double tau) const override;

    void
    measure(StepStatistics<dim> &statistics) const override;

    /** Give @p fields the velocity at @p time (the initial state's). */
    void
    set_velocity(TransportedFields<dim> &fields, const double time) const;

  private:
    /** The largest prescribed speed at the liquid nodes at @p time. */
    double
    largest_speed(const TransportedFields<dim> &fields,
                  const double                  time) const;

    const std::unique_ptr<Function<dim>> velocity;
  };
} // namespace vefs

#endif
