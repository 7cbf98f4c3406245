#include <vefs/base/parameter_entries.h>
#include <vefs/flow/flow_parameters.h>

namespace vefs
{
  using namespace dealii;

  void
  FlowParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Flow");
    {
      add_selection(
        prm,
        "Flow cells",
        flow_level_offset,
        std::vector<std::pair<std::string, unsigned int>>{{"finest", 0},
                                                          {"parents", 1},
                                                          {"grandparents", 2}},
        "The cells of the flow's velocity and pressure. finest: every cell. "
        "parents: where the mesh is finer than 'Maximum level' - 1, the "
        "flow's unknowns are Q1 on the ancestors of the cells on that level, "
        "one level coarser than the transport (as the seed's 5 mm flow "
        "cells over 1 mm transport cells), while the liquid domain is still "
        "cut out of the finest cells: about 2^dim times fewer flow unknowns "
        "in the band around the surface. grandparents: two levels coarser, "
        "about 4^dim times fewer; the mesh partition then keeps each flow "
        "cell's descendants on one rank. Needs 'Mesh refinement/Bulk level' "
        ">= 'Maximum level' minus the offset (1 or 2); not with periodic "
        "walls.");
      prm.add_parameter(
        "Finest cells at contact walls",
        finest_at_contact_walls,
        "With 'Flow cells' coarser than the finest: whether the flow elements "
        "that touch a contact wall keep the finest cells as elements, so that "
        "the contact set lives on the finest cells' wall nodes. On the coarser "
        "elements' wall vertices the contact stops a body while its lowest "
        "point is still about an element above the wall (2D stiff ball, 3.1 mm "
        "cells on 12.5 mm grandparents: first contact 10 ms early, lift-off "
        "9 ms early; with true within 0.1 mm and 3 ms of the finest flow), but "
        "a body that spreads on the wall brings the finest flow cells back "
        "there (3D ball at 2.5 mm on 5 mm parents, first 10 steps: 309,248 "
        "flow unknowns against 193,884). doc/time_step_flow.md.",
        Patterns::Bool());
      prm.add_parameter("Extension layers",
                        extension_layers,
                        "Number of cell layers beyond the liquid into which "
                        "the velocity is extended for the characteristics; "
                        "at least CFL + 2 layers are used, as for the "
                        "band.",
                        Patterns::Integer(1, 100));
      add_selection(
        prm,
        "Outside velocity of cut cells",
        outside_velocity,
        std::vector<std::pair<std::string, OutsideVelocity>>{
          {"automatic", OutsideVelocity::automatic},
          {"solution", OutsideVelocity::solution},
          {"extension at walls", OutsideVelocity::extension_at_walls},
          {"extension", OutsideVelocity::extension}},
        "The velocity that the characteristics see at the vertices of cut "
        "cells that lie outside the liquid (psi > 0): solution (the flow "
        "step's, which its elements extrapolate smoothly: best for liquids; "
        "with extension the standing wave's frequency error goes from 0.74 % "
        "to -0.84 % and its amplitude from a 2.2 % loss to a 5.2 % gain per "
        "period, the broken dam's largest height error from 0.031 to 0.039), "
        "extension (the average of the liquid nodes around, as in the "
        "extension layers beyond), or extension at walls (at such vertices "
        "on slip and contact walls, the solution elsewhere). Where the "
        "surface meets a wall at an acute angle, the wall holds the "
        "solution's normal velocity at zero beside liquid that moves: the 2D "
        "stiff ball's first contact removes 24.7 / 14.7 / 8.0 % of its impact "
        "energy with solution / extension / extension at walls (3.1 mm "
        "cells, PSPG c = 0.05; 13.6 / 5.9 % with extension / extension at "
        "walls and c = 0.01). Extension everywhere makes a ball vibrating "
        "freely gain energy on coarse cells (48.8 / 7.5 / 0.2 % in 0.6 s on "
        "6.25 / 3.1 / 1.6 mm cells); extension at walls gives the liquid "
        "beside the contact line momentum that no force accounts for (in a "
        "step of the stiff ball's contact at most 5.2 / 2.7 / 1.5 % of the "
        "largest step impulse on 6.25 / 3.1 / 1.6 mm cells with c = 0.01; "
        "tests/bouncing_ball_2d_stiff.py allows 3 % at 3.1 mm). Where a "
        "free surface meets a no-slip wall, only the ghost penalty and a "
        "sliver of liquid set the solution: the 3D beam of "
        "prm/oscillating_beam.prm stalls at t = 0.17 s with solution and "
        "runs with extension. doc/bouncing_ball.md, doc/oscillating_beam.md. "
        "automatic: extension at walls for an elastic solid that holds its "
        "shape under its weight (the rule of 'Solver/Pressure "
        "stabilization'; the soft 2D ball of prm/bouncing_ball_2d.prm loses "
        "28.8 J/m with extension against 24.4 by t = 1.35 s), solution "
        "otherwise. The stress at "
        "these vertices: 'Outside stress of cut cells'.");
      add_selection(
        prm,
        "Outside stress of cut cells",
        outside_stress,
        std::vector<std::pair<std::string, OutsideStress>>{
          {"automatic", OutsideStress::automatic},
          {"updated", OutsideStress::updated},
          {"extension", OutsideStress::extension}},
        "The stress at the vertices of cut cells that lie outside the liquid "
        "(psi > 0): updated (the stress update carries it by the cut cell's "
        "mean velocity gradient, bounded by 10 times the stretch of the "
        "cell's liquid nodes) or extension (the average of the liquid nodes "
        "around, as in the extension layers beyond). Nothing in the flow "
        "step resists the stretching of these vertices, and their stress "
        "enters the liquid through the Q1 interpolation: with 'updated' "
        "this is a source of energy. The 2D stiff ball resting on the floor "
        "after its second contact gained 31.5 J/m in 0.15 s with updated and "
        "lost 0.9 J/m with extension; a stiff beam held by a wall, at rest, "
        "gained 5.8 % of its energy in 10 s with updated, 0.33 % with "
        "extension (doc/bouncing_ball.md, doc/oscillating_beam.md). "
        "automatic: extension for an "
        "elastic solid (alpha = 0) and for dumbbells, updated for a "
        "liquid.");
    }
    prm.leave_subsection();
  }

  void
  FlowParameters::resolve(const Regime regime,
                          const bool   dumbbells,
                          const bool   stiff_solid_under_gravity)
  {
    if (outside_velocity == OutsideVelocity::automatic)
      outside_velocity = stiff_solid_under_gravity
                           ? OutsideVelocity::extension_at_walls
                           : OutsideVelocity::solution;
    if (outside_stress == OutsideStress::automatic)
      outside_stress = regime == Regime::elastic_solid || dumbbells
                         ? OutsideStress::extension
                         : OutsideStress::updated;
  }

  void
  SolverParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Solver");
    {
      prm.add_parameter("Tolerance",
                        solver_tolerance,
                        "Relative residual reduction of the Krylov solver.",
                        Patterns::Double(0, 1));
      prm.add_parameter(
        "Contact tolerance",
        contact_solver_tolerance,
        "With contact walls: the relative residual reduction of the solves "
        "while the contact set still changes. They only have to tell which "
        "nodes touch; once a solve leaves the set unchanged the step is "
        "solved again, from there, to 'Tolerance' (and the set checked "
        "again). At or below 'Tolerance': every contact iteration is solved "
        "fully.",
        Patterns::Double(0, 1));
      prm.add_parameter("Maximum iterations",
                        solver_max_iterations,
                        "Iterations after which the Krylov solver gives up "
                        "and stops the run.",
                        Patterns::Integer(1));
      prm.add_parameter("AMG smoother sweeps",
                        amg_smoother_sweeps,
                        "Smoother sweeps per level of the AMG V-cycles for "
                        "the velocity block and for the pressure Laplacian "
                        "of the Schur approximation. The velocity block is "
                        "dominated by the mass matrix rho/tau M when "
                        "rho h^2/(tau mu) is large, and then the smoother does "
                        "most of the work: 4 keeps the iteration counts flat "
                        "under refinement (measured: 2D broken dam, levels "
                        "5-9; 3D; doc/broken_dam.md).",
                        Patterns::Integer(1, 20));
      add_number_or_automatic(
        prm,
        "Solver",
        "Pressure stabilization",
        pressure_stabilization,
        automatic_pressure_stabilization,
        0,
        "Factor c of the PSPG parameter of the Q1-Q1 element, tau_K = c / "
        "(rho/tau + 4 mu / h_K^2). Its consistency error grows with c where "
        "the pressure gradient is large: a stiff beam at rest creeps with "
        "0.25 (its mean sag at 6.25 mm 0.371 mm, growing, against 0.325 / "
        "0.316 mm with 0.05 / 0.01 and Timoshenko's 0.315 mm), and the stiff "
        "ball's first contact loses 8.0 % of its impact energy with 0.05, "
        "5.9 % with 0.01 (3.1 mm cells, 'Flow/Outside velocity of cut "
        "cells = extension at walls'). Smaller c costs Krylov iterations "
        "(10-20 % at 0.02-0.01; the stiff ball: 60 a step with 0.01, 46 with "
        "0.05) and, in soft solids, steps (doc/bouncing_ball.md). "
        "automatic: 0.01 for an elastic solid (alpha = 0, macroscopic "
        "stress, second-order scheme) that holds its shape under its weight, "
        "rho |g| L / (3 G) in (0, 1) with L the cavity's largest extent; "
        "0.25 otherwise.");
      prm.add_parameter(
        "Free surface stabilization",
        free_surface_stabilization,
        "Factor theta in [0, 1] of the free-surface stabilisation (Kaus et "
        "al., PEPI 181, 2010; ASPECT's free surface stabilization theta): "
        "the flow step sees the hydrostatic load change of the surface "
        "moving by tau u.n within the step, theta tau rho |g.n| (u.n)(v.n) "
        "on the free surface where gravity presses it back. 0: the surface "
        "is explicit, stable for tau below about 2 (h / (pi |g|))^(1/2), h "
        "the finest cell (0.010 s at h = 0.8 mm); 0.5 removes that limit "
        "but damps surface waves of frequency omega by about "
        "exp(-pi omega tau / 2) per period (see doc/standing_wave.md).",
        Patterns::Double(0, 1));
      prm.add_parameter("Ghost penalty",
                        ghost_penalty,
                        "Factor gamma of the ghost penalty on the faces of "
                        "cells cut by the free surface (see doc/method.md): "
                        "it keeps a cell with a small liquid part as well "
                        "conditioned as a whole one. 0 switches it off.",
                        Patterns::Double(0));
      prm.add_parameter(
        "Small cut cell mass",
        small_cut_cell_mass,
        "A cut cell whose liquid fraction f is below this number gives each "
        "of its vertices the lumped mass of the fraction (this - f) of the "
        "whole cell, moving with the advected velocity u*: the velocity at "
        "a vertex that only a vanishing liquid part touches, where no "
        "ghost-penalty face reaches it, is otherwise held by that part's "
        "mass alone, and the Stokes solver stalls (the 3D ball with the "
        "gradient-augmented level set, step 151: 2,038 Krylov iterations "
        "in the step with 0, 100 with 0.01, where it then runs to its end; "
        "see doc/time_step_flow.md, step 7). 0 switches it off.",
        Patterns::Double(0, 1));
    }
    prm.leave_subsection();
  }

  void
  SolverParameters::resolve(const bool stiff_solid_under_gravity)
  {
    if (automatic_pressure_stabilization)
      pressure_stabilization = stiff_solid_under_gravity ? 0.01 : 0.25;
  }

  void
  SolverParameters::check() const
  {
    // A relative reduction below round-off cannot be reached: the solver
    // would run to 'Maximum iterations' and blame the time step.
    require(solver_tolerance >= 1e-14 && solver_tolerance < 1,
            "Solver/Tolerance",
            "the relative residual reduction must lie in [1e-14, 1); smaller "
            "ones are below the round-off of the solver in double precision");
    require(contact_solver_tolerance < 1,
            "Solver/Contact tolerance",
            "the relative residual reduction must lie in [0, 1) (0: every "
            "contact iteration is solved to 'Tolerance')");
  }
} // namespace vefs
