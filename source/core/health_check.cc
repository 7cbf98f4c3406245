#include <deal.II/base/mpi.h>

#include <vefs/base/parameter_entries.h>
#include <vefs/core/health_check.h>

#include <cmath>
#include <sstream>

namespace vefs
{
  namespace
  {
    const std::string smaller_steps =
      "reduce 'Time/Time step' or set 'Time/Target CFL'";
    // A stress blows up where the strain of a step is large (the soft 3D
    // ball at 6.25 mm without the strain bound: at step 9).
    const std::string blown_up =
      "the flow has blown up; " + smaller_steps +
      " (with a stress, 'Time/Maximum strain per step')";

    std::string
    number(const double value)
    {
      if (std::isnan(value))
        return "NaN";
      std::ostringstream text;
      text.precision(3);
      text << value;
      return text.str();
    }
  } // namespace

  void
  HealthCheckParameters::declare(dealii::ParameterHandler &prm)
  {
    using namespace dealii;
    prm.enter_subsection("Health check");
    {
      prm.add_parameter("Maximum volume change",
                        max_volume_change,
                        "The run stops (exit status 1) when the relative "
                        "volume change |volume_change| of the statistics "
                        "exceeds this bound: the liquid is no longer the "
                        "one of the scene.",
                        Patterns::Double(0));
      prm.add_parameter(
        "Maximum CFL",
        max_cfl,
        "The run stops (exit status 1) before a step whose "
        "CFL number tau max|u| / h exceeds this bound: the "
        "velocity has blown up or the time step is far too "
        "large. h: the smallest cell of the velocity (the "
        "finest cells, or their parents or grandparents "
        "with 'Flow/Flow cells'; the statistics' column cfl "
        "is on the finest cells). The transport along the "
        "characteristics is stable at any CFL number: the "
        "3D ball of prm/bouncing_ball_seed.prm reaches 60-91 on "
        "its 1.25 mm cells after the impact, 15-23 on its 5 mm "
        "flow cells.",
        Patterns::Double(0));
      prm.add_parameter(
        "Maximum energy growth",
        max_energy_growth,
        "The run stops (exit status 1) after a step that raised the total "
        "energy (kinetic + potential + elastic) by more than this fraction "
        "of the energy above the lowest state (the kinetic and elastic "
        "energies and the potential energy above that of all the liquid in "
        "the lowest corner of the cavity), when that step's elastic wave "
        "number c tau / h (column elastic_wave_number) lies beyond the "
        "trusted 10, for a solid or an Oldroyd-B liquid in a scene that "
        "nothing supplies with energy (no 'velocity' walls, no gravity "
        "along periodic walls, not a prescribed velocity). No equation of "
        "vefs creates energy: such a step is the scheme's failure, a solid "
        "too stiff for the time step. Measured on the 2D stiff ball: the "
        "growth in a step stays below 0.006 up to c tau / h = 100 and "
        "reaches 0.049 at 1000 (doc/reliability.md). 0 turns the check off.",
        Patterns::Double(0));
      prm.add_parameter("Minimum time step fraction",
                        min_time_step_fraction,
                        "The run stops (exit status 1) before a step when "
                        "the step that 'Time/Target CFL' and 'Time/Maximum "
                        "strain per step' allow is below this fraction of "
                        "'Time/Time step': the velocity or its gradient is "
                        "blowing up, and the steps would shrink for ever "
                        "instead. 0 turns the check off.",
                        Patterns::Double(0, 1));
    }
    prm.leave_subsection();
  }

  EnergyWatch::EnergyWatch(const bool                active,
                           const MaterialParameters &material,
                           const CavityParameters   &cavity)
    : active(active)
    , density(material.density)
  {
    // g . x is largest where the potential energy -rho g . x is lowest.
    for (unsigned int d = 0; d < material.gravity.size(); ++d)
      lowest_corner_height +=
        material.gravity[d] * (material.gravity[d] > 0
                                 ? cavity.cavity_upper[d]
                                 : cavity.cavity_lower[d]);
  }

  template <int dim>
  std::string
  EnergyWatch::problem(const HealthCheckParameters &parameters,
                       const StepStatistics<dim>   &s)
  {
    const double total =
      s.kinetic_energy + s.potential_energy + s.elastic_energy;
    const double scale = total + density * s.volume * lowest_corner_height;
    std::string  result;
    if (active && has_previous && parameters.max_energy_growth > 0 &&
        s.elastic_wave_number > trusted_elastic_wave_number &&
        total - previous_total > parameters.max_energy_growth * previous_scale)
      result =
        "the total energy (kinetic + potential + elastic) grew by " +
        number(total - previous_total) + " in one step, " +
        number((total - previous_total) / previous_scale) +
        " of the energy above the lowest state, more than 'Health "
        "check/Maximum energy growth' = " +
        number(parameters.max_energy_growth) +
        ", although nothing in the scene supplies energy" +
        (s.elastic_wave_number > 0
           ? " (an elastic wave crosses " + number(s.elastic_wave_number) +
               " of the finest cells per step, column elastic_wave_number)"
           : std::string()) +
        ": " + smaller_steps +
        " (with a stress, 'Time/Maximum strain per step'; a finer mesh needs "
        "smaller steps still), or raise the bound";
    has_previous   = true;
    previous_total = total;
    previous_scale = scale;
    return result;
  }

  template <int dim>
  bool
  fields_are_finite(const TransportedFields<dim> &fields)
  {
    return dealii::Utilities::MPI::min(
             static_cast<unsigned int>(fields.owned_values_finite()),
             fields.dof_handler.get_triangulation().get_communicator()) == 1;
  }

  std::string
  step_problem(const HealthCheckParameters &p,
               const TimeParameters        &time,
               const unsigned int           step,
               const double                 tau,
               const double                 controlled_tau,
               const double                 cfl,
               const double                 max_velocity,
               const unsigned int           flow_level_offset)
  {
    if (!std::isfinite(cfl) || !std::isfinite(max_velocity))
      return "the largest speed is not finite: " + blown_up;
    const double flow_cfl = cfl / (1u << flow_level_offset);
    if (flow_cfl > p.max_cfl)
      return "the CFL number " + number(flow_cfl) +
             (flow_level_offset > 0
                ? " on the flow's cells ('Flow/Flow cells'; " + number(cfl) +
                    " on the finest cells)"
                : std::string()) +
             " (largest speed " + number(max_velocity) +
             " m/s) exceeds 'Health check/Maximum CFL' = " + number(p.max_cfl) +
             "; " + smaller_steps + ", or raise the bound";
    // A blow-up that the strain bound keeps below the CFL bound shows as
    // steps that shrink without end (an unstable ball: 2,600 steps down to
    // 1e-80 s before the right-hand side overflowed).
    if (controlled_tau < p.min_time_step_fraction * time.time_step)
      return "the time step that 'Time/Target CFL' and 'Time/Maximum strain "
             "per step' allow fell to " +
             number(controlled_tau) +
             " s, below 'Health check/Minimum time step fraction' = " +
             number(p.min_time_step_fraction) + " times 'Time/Time step' (" +
             number(time.time_step) +
             " s): the velocity or its gradient is blowing up, or 'Time/"
             "Maximum strain per step' is far too small; check the scene, or "
             "lower the bound";
    if (step > time.maximum_steps)
      return "more than 'Time/Maximum steps' = " +
             std::to_string(time.maximum_steps) + " steps (time step " +
             number(tau) +
             " s); raise 'Time/Target CFL' or 'Time/Maximum "
             "steps'";
    if (!(tau > 0))
      return "the time step " + number(tau) +
             " is not positive; check "
             "'Time/Time step' and 'Time/Target CFL'";
    return "";
  }

  template <int dim>
  std::string
  state_problem(const HealthCheckParameters  &p,
                const TransportedFields<dim> &fields,
                const StepStatistics<dim>    &s,
                const std::string            &non_finite_statistic)
  {
    if (!fields_are_finite(fields))
      return "the fields (level set, velocity or stress) are not finite: " +
             blown_up;
    if (!non_finite_statistic.empty())
      return "the statistic " + non_finite_statistic +
             " is not finite: " + blown_up;
    if (!(s.volume > 0) || s.liquid_cells == 0)
      return "the liquid has vanished (volume " + number(s.volume) +
             "): it left through open walls ('Walls/...') or was lost; "
             "nothing is left to simulate";
    if (std::abs(s.volume_change) > p.max_volume_change)
      return "the volume change " + number(s.volume_change) +
             " exceeds 'Health check/Maximum volume change' = " +
             number(p.max_volume_change) + "; " + smaller_steps +
             ", raise the 'Mesh refinement' levels, set 'Transport/Volume "
             "correction' = true, or raise the bound";
    return "";
  }

  template std::string
  EnergyWatch::problem<2>(const HealthCheckParameters &,
                          const StepStatistics<2> &);
  template std::string
  EnergyWatch::problem<3>(const HealthCheckParameters &,
                          const StepStatistics<3> &);
  template bool
  fields_are_finite<2>(const TransportedFields<2> &);
  template bool
  fields_are_finite<3>(const TransportedFields<3> &);
  template std::string
  state_problem<2>(const HealthCheckParameters &,
                   const TransportedFields<2> &,
                   const StepStatistics<2> &,
                   const std::string &);
  template std::string
  state_problem<3>(const HealthCheckParameters &,
                   const TransportedFields<3> &,
                   const StepStatistics<3> &,
                   const std::string &);
} // namespace vefs
