#include <deal.II/base/mpi.h>

#include <vefs/flow/prescribed_velocity.h>
#include <vefs/transport/initial_liquid.h>

namespace vefs
{
  template <int dim>
  PrescribedVelocity<dim>::PrescribedVelocity(const std::string &expression)
    : velocity(make_prescribed_velocity<dim>(expression))
  {
  }

  template <int dim>
  std::string
  PrescribedVelocity<dim>::description() const
  {
    return "transport with a prescribed velocity";
  }

  template <int dim>
  void
  PrescribedVelocity<dim>::add_columns(StatisticsFile<dim> &) const
  {
  }

  template <int dim>
  void
  PrescribedVelocity<dim>::set_initial_velocity(
    TransportedFields<dim> &fields) const
  {
    set_velocity(fields, 0);
  }

  template <int dim>
  void
  PrescribedVelocity<dim>::start(TransportedFields<dim> &,
                                 const LiquidDomain<dim> &,
                                 const double,
                                 const bool)
  {
  }

  template <int dim>
  double
  PrescribedVelocity<dim>::largest_speed(const TransportedFields<dim> &fields,
                                         const double time) const
  {
    velocity->set_time(time);
    double speed = 0;
    for (const auto &node : fields.nodes())
      if (fields.level_set(node) <= 0)
        {
          Tensor<1, dim> u;
          for (unsigned int d = 0; d < dim; ++d)
            u[d] = velocity->value(node.point, d);
          speed = std::max(speed, u.norm());
        }
    return Utilities::MPI::max(speed, fields.dof_handler.get_communicator());
  }

  template <int dim>
  TimeStep
  PrescribedVelocity<dim>::time_step(const TimeControl &time,
                                     const StepStatistics<dim> &,
                                     const TransportedFields<dim> &fields) const
  {
    return time.prescribed_time_step(
      [&](const double t) { return largest_speed(fields, t); });
  }

  template <int dim>
  void
  PrescribedVelocity<dim>::set_velocity(TransportedFields<dim> &fields,
                                        const double            time) const
  {
    velocity->set_time(time);
    fields.set_velocity(*velocity);
  }

  template <int dim>
  void
  PrescribedVelocity<dim>::set_advection_velocity(
    TransportedFields<dim> &fields,
    const TimeControl      &time)
  {
    set_velocity(fields, time.time() + time.tau() / 2);
  }

  template <int dim>
  void
  PrescribedVelocity<dim>::advance(TransportedFields<dim> &fields,
                                   const LiquidDomain<dim> &,
                                   const TimeControl &time,
                                   StepStatistics<dim> &)
  {
    set_velocity(fields, time.time() + time.tau());
  }

  template <int dim>
  double
  PrescribedVelocity<dim>::outflow(const double) const
  {
    return 0;
  }

  template <int dim>
  void
  PrescribedVelocity<dim>::measure(StepStatistics<dim> &) const
  {
  }

  template class PrescribedVelocity<2>;
  template class PrescribedVelocity<3>;
} // namespace vefs
