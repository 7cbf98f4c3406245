#include <vefs/base/parameter_entries.h>
#include <vefs/base/time_control.h>

#include <algorithm>
#include <cmath>

namespace vefs
{
  namespace
  {
    double
    norm(const std::vector<double> &vector)
    {
      double squares = 0;
      for (const double component : vector)
        squares += component * component;
      return std::sqrt(squares);
    }
  } // namespace

  using namespace dealii;

  void
  TimeParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Time");
    {
      prm.add_parameter("End time",
                        end_time,
                        "Simulated time span (s), starting at t = 0.",
                        Patterns::Double(0));
      prm.add_parameter("Time step",
                        time_step,
                        "Time step (s). With a positive target CFL number, "
                        "this is the largest time step allowed.",
                        Patterns::Double(0));
      prm.add_parameter("Target CFL",
                        target_cfl,
                        "If positive, the time step is chosen so that "
                        "tau max|u| / h_min equals this number (the method "
                        "is stable for CFL numbers well above 1).",
                        Patterns::Double(0));
      add_number_or_automatic(
        prm,
        "Time",
        "Maximum strain per step",
        max_strain_per_step,
        automatic_max_strain,
        0,
        "If positive (liquids with a stress, elastic solids), the time step "
        "is also bounded so that tau max|grad u| stays below this number: "
        "the stress update resolves the deformation of a step only while "
        "that strain is small. An impact of a soft body raises |grad u| "
        "by orders of magnitude; the step then shrinks for as long as the "
        "impact lasts and grows back to 'Time step' after it. automatic: "
        "0.25 for an elastic solid (alpha = 0), the value every elastic "
        "scene was measured with (doc/bouncing_ball.md), 0 (no bound) for "
        "a liquid.");
      add_selection(
        prm,
        "Strain bound",
        strain_bound_shortens_step,
        std::vector<std::pair<std::string, bool>>{{"step", true},
                                                  {"local", false}},
        "How 'Maximum strain per step' is kept. step: the next time step is "
        "shortened so that tau max|grad u| stays below it (and the "
        "exponential stress update scales tau grad u down where a step "
        "exceeds it all the same); the elastic energy is stored as the "
        "velocity says, but the steps shrink like h at an impact. local: "
        "the time step stays 'Time step' (or what 'Target CFL' allows) and "
        "only the exponential update scales tau grad u down where it is "
        "larger: the stress then stores less elastic energy than the "
        "velocity would, which the energies in the statistics show as "
        "dissipation. Needs 'Stress/Stress update = exponential' and a "
        "positive 'Maximum strain per step'.");
      add_selection(
        prm,
        "Scheme",
        scheme,
        std::vector<std::pair<std::string, TimeScheme>>{
          {"automatic", TimeScheme::automatic},
          {"first order", TimeScheme::first_order},
          {"second order", TimeScheme::second_order}},
        "The splitting of a flow step. automatic: second order unless "
        "'Stress/Stress theta' is below 1, 'Strain bound' is local or the "
        "dumbbells' alpha is not 0, first order then (measured in "
        "doc/time_step_flow.md; for a Newtonian liquid too: the standing "
        "wave's time error at h = L/64, T/40, is 5.0e-5 m against 1.5e-4 m, "
        "the broken dam's heights at level 6 lie within 0.001 of their "
        "converged values, the first-order ones up to 0.003 above, a falling "
        "drop follows the exact parabola). first order: the seed's; the "
        "characteristics trace along the last step's velocity, "
        "the momentum equation is implicit in the forces (backward Euler), "
        "the stress law weighted by 'Stress/Stress theta'. second order: "
        "the characteristics trace along the mid-step velocity u + tau/2 a "
        "(a the acceleration of the last step, carried as a field), the "
        "momentum equation weighs the new forces by 'New force weight' w "
        "and the old ones by 1 - w (w = 1/2: the trapezoidal rule, "
        "velocity Verlet for a body in free fall or a surface wave), the "
        "stress law takes the midpoint velocity and the relaxation is "
        "integrated exactly over the step. A freely falling body then "
        "follows the exact parabola at any step. "
        "See doc/time_step_flow.md. Not used with a prescribed velocity, "
        "which is always traced at mid-step.");
      add_number_or_automatic(
        prm,
        "Time",
        "New force weight",
        new_force_weight,
        automatic_new_force_weight,
        0.5,
        "The weight w of the new forces in the second-order scheme's "
        "momentum equation, 1 - w that of the old ones; at most 1. w > 1/2 "
        "damps an oscillation of frequency omega by about 2 pi (w - 1/2) "
        "omega tau per period: a first-order error. 1/2 (the trapezoidal "
        "rule) makes it second order (the shear wave's amplitude loss at "
        "h = 1/256: orders 1.95 and 1.92 from T/50 to T/200, against 1.23 "
        "and 1.13 with 0.51, test shear_wave_time_order; Waters & King's "
        "time error at level 3 from CFL 6.5 to 0.8: orders 2.08, 2.13, 2.23 "
        "against 1.82, 1.63, 1.36, test waters_king_time_order) but damps "
        "no mode with omega tau >> 1. automatic: 1/2, and 0.51 in a cavity "
        "with contact walls, whose impacts excite such modes: with 1/2 the "
        "contact force alternates from step to step, soft sheets wrinkle at "
        "the cell scale and runs on 1 and 2 ranks part during an impact "
        "(the 2D stiff ball's first contact loses 5.9 % of its kinetic "
        "energy at impact with 0.51, 4.9 % with 1/2; "
        "doc/time_step_flow.md). Only the second-order scheme reads it: "
        "the first-order scheme's forces are all new.");
      prm.add_parameter("Maximum steps",
                        maximum_steps,
                        "Largest number of time steps: a scene whose End "
                        "time / Time step exceeds it is refused before any "
                        "work, and a run whose CFL-limited steps exceed it "
                        "stops.",
                        Patterns::Integer(1));
    }
    prm.leave_subsection();
  }

  void
  TimeParameters::resolve_scheme(const bool   has_second_order_step,
                                 const double stress_theta,
                                 const bool   has_contact_walls)
  {
    // The local strain bound changes the stress update after the momentum
    // equation has assumed the whole one: with the second-order scheme's
    // weaker implicit stiffness the soft ball's impact at 25 ms steps blew
    // up (CFL 66 at its second step on the floor; doc/time_step_flow.md).
    if (scheme == TimeScheme::automatic)
      second_order = has_second_order_step && stress_theta == 1 &&
                     strain_bound_shortens_step;
    else
      second_order = scheme == TimeScheme::second_order;
    require(second_order || automatic_new_force_weight,
            "Time/New force weight",
            "weighs the second-order scheme's forces; the first-order "
            "scheme's are all new: leave it 'automatic'");
    if (!second_order)
      new_force_weight = 1;
    else if (automatic_new_force_weight)
      new_force_weight = has_contact_walls ? impact_new_force_weight
                                           : trapezoidal_new_force_weight;
  }

  void
  TimeParameters::check() const
  {
    require(end_time > 0, "Time/End time", "must be positive");
    require(time_step > 0, "Time/Time step", "must be positive");
    require(new_force_weight <= 1,
            "Time/New force weight",
            "must be 'automatic' or a number from 0.5 to 1");
  }

  void
  OutputParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    {
      prm.add_parameter("Interval",
                        output_interval,
                        "Write visualization files every this many time "
                        "steps (and at the first and last step); 0 writes "
                        "none.",
                        Patterns::Integer(0));
      prm.add_parameter("Time interval",
                        output_time_interval,
                        "If positive, write visualization files at the "
                        "multiples of this time instead (the time step is "
                        "shortened to land on them): with an adaptive time "
                        "step, the frames of a scene then show the same "
                        "instants whatever the resolution.",
                        Patterns::Double(0));
      prm.add_parameter("Verbose",
                        verbose,
                        "Print a progress line per time step and a timing "
                        "summary at the end.",
                        Patterns::Bool());
    }
    prm.leave_subsection();
  }

  TimeControl::TimeControl(const TimeParameters      &parameters,
                           const OutputParameters    &output,
                           const std::vector<double> &gravity,
                           const double               finest_cell_size)
    : end_time(parameters.end_time)
    , time_step(parameters.time_step)
    , target_cfl(parameters.target_cfl)
    , max_strain_per_step(parameters.max_strain_per_step)
    , strain_bound_shortens_step(parameters.strain_bound_shortens_step)
    , output_time_interval(output.output_time_interval)
    , output_interval(output.output_interval)
    , gravity(norm(gravity))
    , finest_cell_size(finest_cell_size)
  {
  }

  void
  TimeControl::resume(const unsigned int step,
                      const double       time,
                      const double       tau)
  {
    current_step = step;
    current_time = time;
    current_tau  = tau;
  }

  TimeStep
  TimeControl::flow_time_step(const double max_velocity,
                              const double max_velocity_gradient) const
  {
    double tau = time_step;
    if (max_strain_per_step > 0 && strain_bound_shortens_step &&
        max_velocity_gradient > 0)
      tau = std::min(tau, max_strain_per_step / max_velocity_gradient);
    if (target_cfl > 0)
      {
        const double h = finest_cell_size;
        if (max_velocity > 0)
          tau = std::min(tau, target_cfl * h / max_velocity);
        else if (gravity > 0)
          // From rest, gravity alone sets the speed: |g| tau after a step,
          // which has crossed CFL cells when tau = sqrt(CFL h / |g|).
          tau = std::min(tau, std::sqrt(target_cfl * h / gravity));
      }
    return {tau, tau};
  }

  TimeStep
  TimeControl::prescribed_time_step(
    const std::function<double(double)> &speed_at) const
  {
    // A prescribed velocity cannot blow up: only the flow's step is watched
    // for collapse.
    double tau = std::min(time_step, end_time - current_time);
    if (target_cfl > 0)
      for (unsigned int iteration = 0; iteration < 10; ++iteration)
        {
          const double speed   = std::max({speed_at(current_time),
                                           speed_at(current_time + tau / 2),
                                           speed_at(current_time + tau)});
          const double allowed = target_cfl * finest_cell_size / speed;
          if (speed == 0 || tau <= allowed * (1 + 1e-12))
            break;
          tau = allowed;
        }
    return {tau, time_step};
  }

  TimeStep
  TimeControl::landed(const TimeStep step) const
  {
    TimeStep landed = step;
    double   target = end_time;
    if (output_time_interval > 0)
      target = std::min(target, next_output_time(current_time));
    const double remaining = target - current_time;
    // Within round-off of the step (fixed steps that divide the interval)
    // the step lands on the target.
    if (remaining <= landed.tau * (1 + 1e-9))
      landed.tau = remaining;
    else if (remaining < (1 + min_step_fraction) * landed.tau)
      // Two halves instead of a full step and a sliver: a sliver costs a
      // whole solve, and the contact force (a velocity change over tau) of
      // a step of 1e-4 tau is noise (3D ball: 92 N at the end, 40 N before).
      landed.tau = remaining / 2;
    return landed;
  }

  void
  TimeControl::start_step(const double tau, const double max_velocity)
  {
    ++current_step;
    current_tau = tau;
    current_cfl = cfl_of(tau, max_velocity);
  }

  void
  TimeControl::end_step()
  {
    current_time += current_tau;
  }

  bool
  TimeControl::is_output_step() const
  {
    if (finished() && (output_interval > 0 || output_time_interval > 0))
      return true;
    if (output_time_interval > 0)
      {
        const double in_intervals = current_time / output_time_interval;
        return std::abs(in_intervals - std::round(in_intervals)) < 1e-9;
      }
    return output_interval > 0 && current_step % output_interval == 0;
  }

  double
  TimeControl::next_output_time(const double time) const
  {
    const double interval = output_time_interval;
    // A time that landed on a multiple up to round-off counts as on it.
    return (std::floor(time / interval + 1e-9) + 1) * interval;
  }
} // namespace vefs
