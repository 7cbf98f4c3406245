#include <vefs/base/expression_check.h>
#include <vefs/base/parameter_entries.h>
#include <vefs/core/parameters.h>
#include <vefs/core/resource_limits.h>

#include <cmath>

namespace vefs
{
  using namespace dealii;

  namespace
  {
    /**
     * The times at which the run evaluates time-dependent expressions:
     * every step and mid-step with the fixed time step, else (or beyond
     * 200 steps) 400 equal parts of the run.
     */
    std::vector<double>
    run_times(const Parameters &p)
    {
      const double steps = std::ceil(p.time.end_time / p.time.time_step);
      const double dt =
        steps <= 200 ? p.time.time_step / 2 : p.time.end_time / 400;
      std::vector<double> times;
      // Multiples, not sums, of dt: the step times exactly.
      for (unsigned int k = 0; k * dt < p.time.end_time; ++k)
        times.push_back(k * dt);
      times.push_back(p.time.end_time);
      return times;
    }

    /** Every muParser expression the scene uses, with its entry name. */
    template <int dim>
    void
    check_expressions(const Parameters &p)
    {
      const ExpressionSampling cavity{p.cavity.cavity_lower,
                                      p.cavity.cavity_upper,
                                      {0.}};
      ExpressionSampling       over_time = cavity;
      over_time.times                    = run_times(p);
      for (unsigned int w = 0; w < 2 * dim; ++w)
        if (p.cavity.wall_type[w] == WallType::velocity)
          {
            // Sampled on the wall only: a pole beyond it does no harm.
            ExpressionSampling wall = over_time;
            const double       x    = w % 2 == 0 ? p.cavity.cavity_lower[w / 2]
                                                 : p.cavity.cavity_upper[w / 2];
            wall.lower[w / 2] = wall.upper[w / 2] = x;
            check_expression<dim>(p.cavity.wall_velocity[w],
                                  dim,
                                  "Walls/" + wall_names[w] + " velocity",
                                  wall);
          }
      check_expression<dim>(p.initial_liquid.initial_velocity,
                            dim,
                            "Initial liquid/Velocity",
                            cavity);
      if (!p.initial_liquid.initial_stress.empty())
        check_expression<dim>(p.initial_liquid.initial_stress,
                              dim * (dim + 1) / 2,
                              "Initial liquid/Stress",
                              cavity);
      if (p.initial_liquid.initial_shape == "expression")
        check_expression<dim>(p.initial_liquid.level_set_expression,
                              1,
                              "Initial liquid/Level set expression",
                              cavity);
      if (p.transport.velocity_is_prescribed())
        check_expression<dim>(p.transport.prescribed_velocity,
                              dim,
                              "Transport/Prescribed velocity",
                              over_time);
      if (!p.transport.exact_final_level_set.empty() &&
          p.transport.exact_final_level_set != "initial")
        check_expression<dim>(p.transport.exact_final_level_set,
                              1,
                              "Transport/Exact final level set",
                              {p.cavity.cavity_lower,
                               p.cavity.cavity_upper,
                               {p.time.end_time}});
    }
  } // namespace

  const std::vector<MovedEntry> Parameters::moved_entries = {
    {"Mesh refinement", "Transport", "Level set interpolation"},
    {"Mesh refinement", "Transport", "Velocity interpolation"},
    {"Mesh refinement", "Transport", "Stress interpolation"},
    {"Mesh refinement", "Transport", "Remap distance"},
    {"Mesh refinement", "Transport", "Redistancing interval"},
    {"Mesh refinement", "Transport", "Volume correction"},
    {"Mesh refinement", "Flow", "Flow cells"},
    {"Mesh refinement", "Flow", "Extension layers"},
    {"Mesh refinement", "Flow", "Outside velocity of cut cells"},
    {"Mesh refinement", "Flow", "Outside stress of cut cells"},
    {"Solver", "Stress", "Stress update"},
    {"Solver", "Stress", "Stress theta"}};

  void
  Parameters::declare(ParameterHandler &prm)
  {
    prm.add_parameter("Dimension",
                      dimension,
                      "Space dimension of the scene: 2 or 3.",
                      Patterns::Integer(2, 3));
    prm.add_parameter("Output directory",
                      output_directory,
                      "Directory for the statistics, the parameters as run "
                      "and the visualization files. Created if missing.",
                      Patterns::DirectoryName());
    time.declare(prm);
    health_check.declare(prm);
    cavity.declare(prm);
    material.declare(prm);
    stress.declare(prm);
    initial_liquid.declare(prm);
    mesh.declare(prm);
    transport.declare(prm);
    flow.declare(prm);
    solver.declare(prm);
    postprocess.declare(prm);
    checkpoint.declare(prm);
    output.declare(prm);
  }

  void
  Parameters::check_for_ranks(const unsigned int n_ranks) const
  {
    const auto periodic = cavity.periodic_directions();
    if (periodic.empty() || n_ranks == 1)
      return;
    // deal.II 9.4 does not make the constraints of a cell corner shared by
    // two periodic pairs consistent across ranks, and in 3D the flow of a
    // periodic scene differs on 2 ranks already with one pair (measured:
    // 0.7157 against 0.7143 m/s after one step of a 3D shear flow).
    require(periodic.size() == 1,
            "Walls/" + wall_names[2 * periodic.back()],
            "periodic walls in more than one direction need a single MPI "
            "rank in this version; allowed on several ranks: one periodic "
            "pair in 2D");
    require(dimension == 2,
            "Walls/" + wall_names[2 * periodic.back()],
            "periodic walls in 3D need a single MPI rank in this version; "
            "allowed on several ranks: one periodic pair in 2D");
  }

  void
  Parameters::resolve_automatic_entries()
  {
    // The entries whose best value depends on the material (the measured
    // settings of the elastic scenes: doc/bouncing_ball.md).
    const Regime regime = material.regime();
    transport.resolve_level_set(dimension,
                                mesh.band_placement ==
                                  BandPlacement::predicted_one_change);
    stress.resolve();
    // Steps kept through impacts (the seed's fixed steps) reach CFL
    // numbers of tens: the band is then refined ahead of the surface
    // (doc/bouncing_ball_3d_study.md, "Settings of the fine scenes").
    const bool steps_fixed =
      !time.strain_bound_shortens_step && time.target_cfl == 0;
    mesh.resolve(steps_fixed && transport.feet_linear_without_remap());
    if (time.automatic_max_strain)
      time.max_strain_per_step = regime == Regime::elastic_solid ? 0.25 : 0;
    // The second-order scheme's relaxation has no dumbbell counterpart
    // (doc/dumbbells.md).
    time.resolve_scheme(!transport.velocity_is_prescribed() &&
                          !(material.has_dumbbells() && material.alpha != 0),
                        stress.stress_theta,
                        cavity.has_contact_walls(dimension));
    // Cubic interpolation at the feet keeps the elastic waves of a solid
    // that holds its shape under its weight; a soft one pays for it in steps
    // and solves (doc/bouncing_ball.md, "What `automatic` gives a stiff
    // solid").
    const double strain = weight_strain();
    const bool   stiff_solid_under_gravity =
      regime == Regime::elastic_solid && !material.has_dumbbells() &&
      time.second_order && strain > 0 && strain < 1;
    transport.resolve(mesh.band_predicted(),
                      mesh.band_in_one_change(),
                      stiff_solid_under_gravity,
                      dimension);
    solver.resolve(stiff_solid_under_gravity);
    stress.resolve_nodal_stress(stiff_solid_under_gravity);
    flow.resolve(regime, material.has_dumbbells(), stiff_solid_under_gravity);
  }

  double
  Parameters::weight_strain() const
  {
    if (material.regime() == Regime::newtonian)
      return 0;
    double g = 0, extent = 0;
    for (unsigned int d = 0; d < material.gravity.size(); ++d)
      g += material.gravity[d] * material.gravity[d];
    for (unsigned int d = 0; d < cavity.cavity_lower.size(); ++d)
      extent =
        std::max(extent,
                 std::abs(cavity.cavity_upper[d] - cavity.cavity_lower[d]));
    return material.density * std::sqrt(g) * extent /
           (3 * material.shear_modulus());
  }

  void
  Parameters::check()
  {
    warnings.clear();
    // The automatic entries read the cavity's extent.
    cavity.check(dimension);
    resolve_automatic_entries();
    time.check();
    material.check(dimension);
    solver.check();
    postprocess.check(dimension, cavity);
    initial_liquid.check(dimension, cavity, warnings);
    mesh.check();

    // The cross-check: what one module's entries ask of another's.
    require(material.regime() != Regime::newtonian ||
              initial_liquid.initial_stress.empty(),
            "Initial liquid/Stress",
            "a Newtonian liquid (relaxation time 0) has no extra stress; "
            "leave it empty or give a positive relaxation time");
    require(!transport.velocity_is_prescribed() ||
              initial_liquid.initial_stress.empty(),
            "Initial liquid/Stress",
            "with a prescribed velocity the flow (and its stress) is not "
            "solved; leave it empty");
    require(time.strain_bound_shortens_step ||
              (stress.stress_update == StressUpdate::exponential &&
               time.max_strain_per_step > 0),
            "Time/Strain bound",
            "'local' scales the strain down in the exponential stress update "
            "only: it needs 'Stress/Stress update = exponential' and a "
            "positive 'Time/Maximum strain per step'");
    require(!material.has_dumbbells() ||
              stress.nodal_stress == NodalStress::vertex_average,
            "Stress/Nodal stress",
            "the dumbbells' fields reach the nodes by the vertex average only: "
            "use 'vertex average' or 'automatic'");
    require(transport.volume_correction_shift == ShiftWeight::uniform ||
              transport.remap_distance == 0,
            "Transport/Volume correction shift",
            "'surface speed' moves the level set by a field, which the "
            "characteristics between remaps do not carry: it needs "
            "'Transport/Remap distance = 0' (the default of flows)");
    require(!mesh.band_predicted() || transport.remap_distance == 0,
            "Mesh refinement/Band placement",
            "'predicted' adapts the mesh before every advection; between "
            "remaps the mesh stays: it needs 'Transport/Remap distance = 0'");
    require(!mesh.band_in_one_change() || transport.feet_linear(),
            "Mesh refinement/Band placement",
            "'predicted, one change' keeps the Q1 fields of the coarsened "
            "cells only: it needs 'linear' for 'Level set interpolation', "
            "'Velocity interpolation' and 'Stress interpolation' (in "
            "'Transport')");
    require(flow.flow_level_offset == 0 || cavity.periodic_directions().empty(),
            "Flow/Flow cells",
            "'parents' and 'grandparents' are not implemented with periodic "
            "walls: use 'finest'");
    require(flow.flow_level_offset == 0 ||
              (mesh.max_level >= flow.flow_level_offset &&
               mesh.bulk_level + flow.flow_level_offset >= mesh.max_level),
            "Flow/Flow cells",
            "'parents' needs 'Mesh refinement/Bulk level' >= 'Mesh "
            "refinement/Maximum level' - 1 and 'Maximum level' >= 1, "
            "'grandparents' 'Bulk level' >= 'Maximum level' - 2 and "
            "'Maximum level' >= 2: the flow's cells then all lie on one "
            "level");

    require(!time.second_order || stress.stress_theta == 1,
            "Stress/Stress theta",
            "weighs the stress law of 'Time/Scheme = first order' only; the "
            "second-order scheme uses the midpoint velocity: leave it 1");
    require(!time.second_order || time.strain_bound_shortens_step,
            "Time/Strain bound",
            "'local' changes the stress update after the second-order "
            "scheme's momentum equation has assumed the whole one, which "
            "is unstable at an impact: use 'Time/Scheme = first order' (or "
            "'automatic') with it");
    require(!time.second_order || !transport.velocity_is_prescribed(),
            "Time/Scheme",
            "a prescribed velocity is always traced at mid-step and solves "
            "no flow: leave it 'automatic' or 'first order'");
    if (material.has_dumbbells())
      {
        // The dumbbells' update carries the fields by a linear map whose
        // second moment is the exponential update's (doc/dumbbells.md).
        require(stress.stress_update == StressUpdate::exponential,
                "Stress/Stress update",
                "dumbbells are carried by the exponential update: leave it "
                "'automatic' or set 'exponential'");
        require(flow.extends_outside_stress(),
                "Flow/Outside stress of cut cells",
                "'updated' bounds the stress outside the liquid, which the "
                "dumbbells' fields cannot follow: leave it 'automatic' or "
                "set 'extension'");
        require(!time.second_order || material.alpha == 0,
                "Time/Scheme",
                "the second-order scheme's relaxation has no dumbbell "
                "counterpart: use 'first order' for dumbbells with alpha = 1");
        require(!transport.velocity_is_prescribed(),
                "Material/Stress model",
                "with a prescribed velocity no stress is solved: use "
                "'macroscopic'");
      }
    require(!postprocess.energy_budget || !transport.velocity_is_prescribed(),
            "Postprocess/Energy budget",
            "a prescribed velocity solves no flow and has no energy budget: "
            "leave it false");

    check_resources(*this);

    if (dimension == 2)
      check_expressions<2>(*this);
    else
      check_expressions<3>(*this);
  }
} // namespace vefs
