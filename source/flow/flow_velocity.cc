#include <vefs/flow/flow_velocity.h>
#include <vefs/stress/dumbbells.h>
#include <vefs/stress/stress.h>
#include <vefs/transport/field_extension.h>

#include <algorithm>
#include <cmath>

namespace vefs
{
  template <int dim>
  FlowVelocity<dim>::FlowVelocity(const FlowStepParameters &parameters,
                                  const Rheology<dim>      &rheology,
                                  StokesStep<dim>          &flow,
                                  TimerOutput              &timer)
    : parameters(parameters)
    , rheology(rheology)
    , flow(flow)
    , timer(timer)
  {
  }

  template <int dim>
  std::string
  FlowVelocity<dim>::description() const
  {
    switch (parameters.material.regime())
      {
        case Regime::newtonian:
          return "Newtonian free-surface flow";
        case Regime::oldroyd_b:
          return "Oldroyd-B free-surface flow";
        case Regime::elastic_solid:
          return parameters.material.solvent_viscosity > 0
                   ? "Kelvin-Voigt elastic solid (neo-Hookean + viscous)"
                   : "neo-Hookean elastic solid";
      }
    return "";
  }

  template <int dim>
  void
  FlowVelocity<dim>::add_columns(StatisticsFile<dim> &statistics) const
  {
    if (rheology.has_stress())
      {
        statistics.add_column("max_velocity_gradient", [](const auto &s) {
          return s.max_velocity_gradient;
        });
        if (parameters.stress.stress_update == StressUpdate::exponential &&
            parameters.max_strain_per_step > 0)
          statistics.add_column("strain_limited_points", [](const auto &s) {
            return s.strain_limited_points;
          });
      }
    if (parameters.energy_budget)
      {
        statistics.add_column("energy_change_transport", [](const auto &s) {
          return s.energy_change_transport;
        });
        statistics.add_column("energy_change_flow", [](const auto &s) {
          return s.energy_change_flow;
        });
        statistics.add_column("energy_change_extension", [](const auto &s) {
          return s.energy_change_extension;
        });
        if (flow.has_contact_walls())
          statistics.add_column("energy_change_contact", [](const auto &s) {
            return s.energy_change_contact;
          });
        if (budgets_stress_update())
          statistics.add_column("energy_change_stress_update",
                                [](const auto &s) {
                                  return s.energy_change_stress_update;
                                });
      }
    if (flow.has_contact_walls())
      {
        statistics.add_column("contact_force",
                              [](const auto &s) { return s.contact_force; });
        statistics.add_column(dim == 2 ? "contact_length" : "contact_area",
                              [](const auto &s) { return s.contact_measure; });
        statistics.add_column("unsettled_contact_set", [](const auto &s) {
          return s.unsettled_contact_set;
        });
        statistics.add_column("stokes_solves",
                              [](const auto &s) { return s.stokes_solves; });
      }
  }

  template <int dim>
  void
  FlowVelocity<dim>::set_initial_velocity(TransportedFields<dim> &) const
  {
    // The flow starts from the scene's 'Initial liquid/Velocity'.
  }

  template <int dim>
  void
  FlowVelocity<dim>::start(TransportedFields<dim>  &fields,
                           const LiquidDomain<dim> &domain,
                           const double             time,
                           const bool               new_run)
  {
    flow.setup(domain, time);
    if (new_run && fields.has_acceleration())
      {
        find_initial_acceleration(fields);
        initial_contact_reaction = flow.contact_force();
      }
    if (parameters.energy_budget)
      last_energy = energy(fields, domain).total();
  }

  template <int dim>
  MechanicalEnergy
  FlowVelocity<dim>::energy(const TransportedFields<dim> &fields,
                            const LiquidDomain<dim>      &domain) const
  {
    TimerOutput::Scope scope(timer, "energy budget");
    return mechanical_energy(fields, domain, parameters.material, rheology);
  }

  template <int dim>
  bool
  FlowVelocity<dim>::budgets_stress_update() const
  {
    return parameters.energy_budget && rheology.has_stress() &&
           !parameters.material.has_dumbbells();
  }

  template <int dim>
  TimeStep
  FlowVelocity<dim>::time_step(const TimeControl         &time,
                               const StepStatistics<dim> &last,
                               const TransportedFields<dim> &) const
  {
    return time.flow_time_step(last.max_velocity, last.max_velocity_gradient);
  }

  template <int dim>
  void
  FlowVelocity<dim>::set_advection_velocity(TransportedFields<dim> &fields,
                                            const TimeControl      &time)
  {
    // The fields hold the flow's last velocity, extended beyond the liquid;
    // the second-order scheme traces along the mid-step velocity u + tau/2 a
    // (once per step: a mesh change before the advection carries it along).
    if (!fields.has_acceleration() || trace_velocity_in_fields)
      return;
    add_acceleration_to_velocity(fields, time.tau() / 2);
    trace_velocity_in_fields = true;
  }

  template <int dim>
  void
  FlowVelocity<dim>::finish_advection(TransportedFields<dim> &fields,
                                      const TimeControl      &time)
  {
    // (u + tau/2 a)(X) - tau/2 a(X) = u(X): exact for the Q1 interpolation
    // of both, to the limiter's clipping for a limited cubic velocity.
    if (!trace_velocity_in_fields)
      return;
    add_acceleration_to_velocity(fields, -time.tau() / 2);
    trace_velocity_in_fields = false;
  }

  template <int dim>
  void
  FlowVelocity<dim>::add_acceleration_to_velocity(
    TransportedFields<dim> &fields,
    const double            factor) const
  {
    for (const auto &node : fields.nodes())
      fields.set_velocity(node,
                          fields.velocity(node) +
                            factor * fields.acceleration(node));
    fields.finalize();
  }

  template <int dim>
  void
  FlowVelocity<dim>::set_acceleration(
    TransportedFields<dim>                            &fields,
    const typename TransportedFields<dim>::VectorType &advected,
    const typename TransportedFields<dim>::VectorType &known,
    const double                                       tau) const
  {
    const double w = parameters.new_force_weight;
    for (const auto &node : fields.nodes())
      if (known(node.dofs[0]) != 0)
        fields.set_acceleration(
          node,
          (1 / (w * tau)) *
              (fields.velocity(node) -
               TransportedFields<dim>::velocity_slots(advected, node)) -
            ((1 - w) / w) * fields.acceleration_slots(advected, node));
    fields.finalize();
  }

  template <int dim>
  void
  FlowVelocity<dim>::find_initial_acceleration(TransportedFields<dim> &fields)
  {
    TimerOutput::Scope scope(timer, "initial acceleration");
    // Over one 'Time step': over a thousandth of it a body in free fall got
    // accelerations from -47 to 66 m/s^2 instead of g (the pressure
    // stabilisation weakens as the step shrinks).
    const double tau = parameters.time_step;
    solve_step(fields, tau);
    typename TransportedFields<dim>::VectorType initial, known;
    fields.copy_to(initial);
    fields.initialize_vector(known);
    flow.copy_velocity_to(fields, known);
    // The initial acceleration a* is zero: a = (u - u0) / (w tau).
    set_acceleration(fields, initial, known, tau);
    for (const auto &node : fields.nodes())
      fields.set_velocity(node,
                          TransportedFields<dim>::velocity_slots(initial,
                                                                 node));
    fields.finalize();
    unflag_extended_velocity_nodes(fields, known);
    extend_flow_fields(fields,
                       known,
                       parameters.flow.extension_layers,
                       acceleration_components(fields));
  }

  template <int dim>
  void
  FlowVelocity<dim>::unflag_extended_velocity_nodes(
    const TransportedFields<dim>                &fields,
    typename TransportedFields<dim>::VectorType &known) const
  {
    switch (parameters.flow.resolved_outside_velocity())
      {
        case OutsideVelocity::extension:
          unflag_nodes_outside_liquid(fields, known);
          break;
        case OutsideVelocity::extension_at_walls:
          // The wall holds the solution's normal velocity there at zero,
          // beside liquid that moves (doc/bouncing_ball.md).
          unflag_nodes_outside_liquid<dim>(
            fields,
            known,
            [this](const Point<dim> &p) {
              return parameters.cavity.on_slip_or_contact_wall(p);
            });
          break;
        case OutsideVelocity::automatic: // resolved before
        case OutsideVelocity::solution:
          break;
      }
  }

  template <int dim>
  void
  FlowVelocity<dim>::advance(TransportedFields<dim>  &fields,
                             const LiquidDomain<dim> &domain,
                             const TimeControl       &time,
                             StepStatistics<dim>     &statistics)
  {
    statistics.linear_iterations = 0;
    if (parameters.material.has_dumbbells())
      {
        // The advection and the mesh change interpolated the fields q_i and
        // the stress apart; the stress, interpolated like the macroscopic
        // run's, is the one to keep (doc/dumbbells.md, "Interpolation").
        TimerOutput::Scope scope(timer, "4 stress update");
        match_dumbbells_to_stress(fields, rheology);
      }
    if (parameters.energy_budget)
      {
        const double advected              = energy(fields, domain).total();
        statistics.energy_change_transport = advected - last_energy;
        last_energy                        = advected;
      }
    {
      TimerOutput::Scope scope(timer, "3 diffusion: setup");
      flow.setup(domain, time.time() + time.tau());
    }
    const SolveReport solved         = solve_step(fields, time.tau());
    statistics.linear_iterations     = solved.iterations;
    statistics.unsettled_contact_set = solved.contact_set_settled ? 0 : 1;
    statistics.stokes_solves         = solved.solves;
    if (parameters.energy_budget && flow.has_contact_walls())
      {
        // The fields still hold u*, the solution u.
        TimerOutput::Scope scope(timer, "energy budget");
        statistics.energy_change_contact =
          time.tau() * parameters.new_force_weight * flow.contact_power(fields);
      }
    update_fields(fields,
                  domain,
                  time.tau(),
                  time.expected_cfl(),
                  time.step(),
                  statistics);
    if (parameters.energy_budget)
      {
        const double extended              = energy(fields, domain).total();
        statistics.energy_change_extension = extended - last_energy;
        last_energy                        = extended;
      }
  }

  template <int dim>
  typename FlowVelocity<dim>::SolveReport
  FlowVelocity<dim>::solve_step(const TransportedFields<dim> &fields,
                                const double                  tau)
  {
    {
      TimerOutput::Scope scope(timer, "3 diffusion: assembly");
      flow.assemble(fields, tau);
    }
    {
      TimerOutput::Scope scope(timer, "3 diffusion: preconditioner");
      flow.build_preconditioner();
    }
    return solve_with_contact(fields, tau);
  }

  template <int dim>
  typename FlowVelocity<dim>::SolveReport
  FlowVelocity<dim>::solve_with_contact(const TransportedFields<dim> &fields,
                                        const double                  tau)
  {
    // Contact walls: solve again while the contact set changes
    // (doc/walls.md, "Contact walls"); a few times at the most. Until a solve
    // leaves the set unchanged the solves only have to tell which nodes
    // touch: loosely; the step ends with a full solve that leaves the set
    // unchanged too.
    // The last update reads the reactions of the step's solution: the
    // contact force (its impulse the body's momentum change) and the energy
    // budget's contact power are those the solution felt, also where the
    // set still changed after the last solve allowed.
    SolveReport report;
    bool        full_solve = !flow.touches_contact_walls() ||
                      parameters.solver.contact_solver_tolerance <=
                        parameters.solver.solver_tolerance;
    for (unsigned int solves = 1;; ++solves)
      {
        {
          TimerOutput::Scope scope(timer, "3 diffusion: solve");
          report.iterations +=
            flow.solve(full_solve ? parameters.solver.solver_tolerance
                                  : parameters.solver.contact_solver_tolerance);
        }
        bool changed;
        {
          TimerOutput::Scope scope(timer, "3 diffusion: contact set");
          changed = flow.update_contact(fields, tau);
        }
        report.contact_set_settled = !changed;
        report.solves              = solves;
        if (full_solve && (!changed || solves >= max_contact_iterations))
          break;
        if (!changed || solves + 1 >= max_contact_iterations)
          full_solve = true;
      }
    return report;
  }

  template <int dim>
  void
  FlowVelocity<dim>::update_fields(TransportedFields<dim>  &fields,
                                   const LiquidDomain<dim> &domain,
                                   const double             tau,
                                   const double             expected_cfl,
                                   const unsigned int       step,
                                   StepStatistics<dim>     &statistics)
  {
    // The next characteristics trace back through the band around the
    // liquid: give it the new velocity, as far as the surface can move.
    TimerOutput::Scope scope(timer, "velocity extension");
    typename TransportedFields<dim>::VectorType known;
    fields.initialize_vector(known);
    // With 'Stress theta' < 1 the stress law sees theta u + (1 - theta) u*,
    // and the second-order scheme's acceleration needs u* and a*: keep them
    // before the new velocity replaces them.
    const double theta                    = rheology.implicit_weight();
    double       pointwise_elastic_energy = 0;
    typename TransportedFields<dim>::VectorType blended_velocity;
    if ((rheology.has_stress() && theta < 1) || fields.has_acceleration())
      fields.copy_to(blended_velocity);
    flow.copy_velocity_to(fields, known);
    if (fields.has_acceleration())
      set_acceleration(fields, blended_velocity, known, tau);
    if (rheology.has_stress())
      {
        TimerOutput::Scope scope(timer, "4 stress update");
        // The update reads the velocity components of the vector and writes
        // the stress components of the fields.
        fields.blend_velocity_into(blended_velocity, theta);
        if (budgets_stress_update())
          {
            // What the flow step did work against is the stress at its
            // quadrature points: the reference for the nodal update.
            TimerOutput::Scope scope(timer, "energy budget");
            pointwise_elastic_energy =
              elastic_energy_of_pointwise_update(fields,
                                                 blended_velocity,
                                                 domain,
                                                 rheology,
                                                 tau);
          }
        const StressUpdateReport report =
          parameters.material.has_dumbbells()
            ? update_dumbbells(
                fields,
                blended_velocity,
                domain,
                rheology,
                tau,
                dumbbells::increments<dim>(fields.n_dumbbell_fields,
                                           parameters.material.dumbbell_seed,
                                           step))
            : update_stress(fields,
                            blended_velocity,
                            domain,
                            rheology,
                            tau,
                            parameters.flow.extends_outside_stress(),
                            parameters.stress.nodal_stress);
        statistics.max_velocity_gradient = report.max_velocity_gradient;
        statistics.strain_limited_points = report.strain_limited_points;
      }
    if (parameters.energy_budget)
      {
        const MechanicalEnergy updated = energy(fields, domain);
        statistics.energy_change_flow  = updated.total() - last_energy;
        if (budgets_stress_update())
          statistics.energy_change_stress_update =
            updated.elastic - pointwise_elastic_energy;
        last_energy = updated.total();
      }
    const unsigned int layers =
      std::max<unsigned int>(parameters.flow.extension_layers,
                             std::ceil(expected_cfl) + 2);
    // The vertices of cut cells outside the liquid keep the flow step's
    // velocity and the updated stress, or take the extension ('Outside
    // velocity/stress of cut cells').
    const bool extend_stress =
      fields.has_stress() && parameters.flow.extends_outside_stress();
    if (parameters.flow.resolved_outside_velocity() ==
        (extend_stress ? OutsideVelocity::extension
                       : OutsideVelocity::solution))
      {
        if (extend_stress)
          unflag_nodes_outside_liquid(fields, known);
        extend_flow_fields(fields, known, layers, flow_components(fields));
      }
    else
      {
        auto known_stress = known;
        unflag_extended_velocity_nodes(fields, known);
        if (extend_stress)
          unflag_nodes_outside_liquid(fields, known_stress);
        extend_flow_fields(fields,
                           known,
                           layers,
                           velocity_and_acceleration_components(fields));
        if (fields.has_stress())
          extend_flow_fields(fields,
                             known_stress,
                             layers,
                             stress_components(fields));
      }
    if (parameters.material.has_dumbbells())
      // The extension averaged the fields q_i and the stress apart.
      match_dumbbells_to_stress(fields, rheology);
  }

  template <int dim>
  double
  FlowVelocity<dim>::outflow(const double tau) const
  {
    return tau * flow.outflow_rate();
  }

  template <int dim>
  void
  FlowVelocity<dim>::measure(StepStatistics<dim> &statistics) const
  {
    statistics.dofs = flow.n_dofs();
    // The momentum equation of the step, times w tau, reads rho (u - u*) =
    // tau (w F^{n+1} + (1 - w) F^n): the walls' impulse over the step is
    // tau times the mean of their reactions at its ends, weighted as the
    // forces are. The reaction itself alternates from step to step where
    // the contact set changes (w = 0.51 damps its alternating part slowly;
    // the motion stays smooth: doc/time_step_flow.md); the mean does not.
    const double w           = parameters.new_force_weight;
    const double reaction    = flow.contact_force();
    const double previous    = statistics.step == 1 ? initial_contact_reaction
                                                    : statistics.contact_reaction;
    statistics.contact_force = w * reaction + (1 - w) * previous;
    statistics.contact_reaction = reaction;
    statistics.contact_measure  = flow.contact_measure();
  }

  template class FlowVelocity<2>;
  template class FlowVelocity<3>;
} // namespace vefs
