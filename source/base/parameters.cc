#include <deal.II/base/utilities.h>

#include <vefs/base/expression_check.h>
#include <vefs/base/parameters.h>
#include <vefs/base/resource_limits.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <iostream>
#include <map>
#include <sstream>

namespace vefs
{
  using namespace dealii;

  namespace
  {
    std::vector<double>
    to_doubles(const std::string &text)
    {
      return Utilities::string_to_double(
        Utilities::split_string_list(text, ','));
    }

    std::string
    entry_error(const std::string &entry, const std::string &what)
    {
      return "entry '" + entry + "': " + what;
    }

    void
    require(const bool         condition,
            const std::string &entry,
            const std::string &what)
    {
      if (!condition)
        throw InputError(entry_error(entry, what));
    }

    const std::map<std::string, WallType> wall_type_names = {
      {"no-slip", WallType::no_slip},
      {"slip", WallType::slip},
      {"open", WallType::open},
      {"velocity", WallType::velocity},
      {"periodic", WallType::periodic},
      {"contact", WallType::contact}};

    /**
     * The times at which the run evaluates time-dependent expressions:
     * every step and mid-step with the fixed time step, else (or beyond
     * 200 steps) 400 equal parts of the run.
     */
    std::vector<double>
    run_times(const Parameters &p)
    {
      const double steps = std::ceil(p.end_time / p.time_step);
      const double dt    = steps <= 200 ? p.time_step / 2 : p.end_time / 400;
      std::vector<double> times;
      // Multiples, not sums, of dt: the step times exactly.
      for (unsigned int k = 0; k * dt < p.end_time; ++k)
        times.push_back(k * dt);
      times.push_back(p.end_time);
      return times;
    }

    /** Every muParser expression the scene uses, with its entry name. */
    template <int dim>
    void
    check_expressions(const Parameters &p)
    {
      const ExpressionSampling cavity{p.cavity_lower, p.cavity_upper, {0.}};
      ExpressionSampling       over_time = cavity;
      over_time.times                    = run_times(p);
      for (unsigned int w = 0; w < 2 * dim; ++w)
        if (p.wall_type[w] == WallType::velocity)
          {
            // Sampled on the wall only: a pole beyond it does no harm.
            ExpressionSampling wall = over_time;
            const double       x =
              w % 2 == 0 ? p.cavity_lower[w / 2] : p.cavity_upper[w / 2];
            wall.lower[w / 2] = wall.upper[w / 2] = x;
            check_expression<dim>(p.wall_velocity[w],
                                  dim,
                                  "Walls/" + wall_names[w] + " velocity",
                                  wall);
          }
      check_expression<dim>(p.initial_velocity,
                            dim,
                            "Initial liquid/Velocity",
                            cavity);
      if (!p.initial_stress.empty())
        check_expression<dim>(p.initial_stress,
                              dim * (dim + 1) / 2,
                              "Initial liquid/Stress",
                              cavity);
      if (p.initial_shape == "expression")
        check_expression<dim>(p.level_set_expression,
                              1,
                              "Initial liquid/Level set expression",
                              cavity);
      if (p.velocity_is_prescribed())
        check_expression<dim>(p.prescribed_velocity,
                              dim,
                              "Transport/Prescribed velocity",
                              over_time);
      if (!p.exact_final_level_set.empty() &&
          p.exact_final_level_set != "initial")
        check_expression<dim>(p.exact_final_level_set,
                              1,
                              "Transport/Exact final level set",
                              {p.cavity_lower, p.cavity_upper, {p.end_time}});
    }
  } // namespace

  void
  Parameters::declare(ParameterHandler &prm)
  {
    prm.declare_entry("Dimension",
                      "2",
                      Patterns::Integer(2, 3),
                      "Space dimension of the scene: 2 or 3.");
    prm.declare_entry("Output directory",
                      "output",
                      Patterns::DirectoryName(),
                      "Directory for the statistics, the parameters as run "
                      "and the visualization files. Created if missing.");
    prm.declare_entry("Gravity",
                      "0, -9.81",
                      Patterns::List(Patterns::Double(), 2, 3),
                      "Gravitational acceleration vector (m/s^2), one "
                      "component per dimension.");

    prm.enter_subsection("Time");
    {
      prm.declare_entry("End time",
                        "0.18",
                        Patterns::Double(0),
                        "Simulated time span (s), starting at t = 0.");
      prm.declare_entry("Time step",
                        "0.001",
                        Patterns::Double(0),
                        "Time step (s). With a positive target CFL number, "
                        "this is the largest time step allowed.");
      prm.declare_entry("Target CFL",
                        "0",
                        Patterns::Double(0),
                        "If positive, the time step is chosen so that "
                        "tau max|u| / h_min equals this number (the method "
                        "is stable for CFL numbers well above 1).");
      prm.declare_entry(
        "Maximum strain per step",
        "0",
        Patterns::Double(0),
        "If positive (liquids with a stress, elastic solids), the time step "
        "is also bounded so that tau max|grad u| stays below this number: "
        "the stress update resolves the deformation of a step only while "
        "that strain is small. An impact of a soft body raises |grad u| "
        "by orders of magnitude; the step then shrinks for as long as the "
        "impact lasts and grows back to 'Time step' after it.");
      prm.declare_entry(
        "Strain bound",
        "step",
        Patterns::Selection("step|local"),
        "How 'Maximum strain per step' is kept. step: the next time step is "
        "shortened so that tau max|grad u| stays below it (and the "
        "exponential stress update scales tau grad u down where a step "
        "exceeds it all the same); the elastic energy is stored as the "
        "velocity says, but the steps shrink like h at an impact. local: "
        "the time step stays 'Time step' (or what 'Target CFL' allows) and "
        "only the exponential update scales tau grad u down where it is "
        "larger: the stress then stores less elastic energy than the "
        "velocity would, which the energies in the statistics show as "
        "dissipation. Needs 'Solver/Stress update = exponential' and a "
        "positive 'Maximum strain per step'.");
      prm.declare_entry("Maximum steps",
                        "100000",
                        Patterns::Integer(1),
                        "Largest number of time steps: a scene whose End "
                        "time / Time step exceeds it is refused before any "
                        "work, and a run whose CFL-limited steps exceed it "
                        "stops.");
    }
    prm.leave_subsection();

    prm.enter_subsection("Health check");
    {
      prm.declare_entry("Maximum volume change",
                        "0.2",
                        Patterns::Double(0),
                        "The run stops (exit status 1) when the relative "
                        "volume change |volume_change| of the statistics "
                        "exceeds this bound: the liquid is no longer the "
                        "one of the scene.");
      prm.declare_entry("Maximum CFL",
                        "50",
                        Patterns::Double(0),
                        "The run stops (exit status 1) before a step whose "
                        "CFL number tau max|u| / h_min exceeds this bound: "
                        "the velocity has blown up or the time step is far "
                        "too large.");
      prm.declare_entry("Minimum time step fraction",
                        "1e-6",
                        Patterns::Double(0, 1),
                        "The run stops (exit status 1) before a step when "
                        "the step that 'Time/Target CFL' and 'Time/Maximum "
                        "strain per step' allow is below this fraction of "
                        "'Time/Time step': the velocity or its gradient is "
                        "blowing up, and the steps would shrink for ever "
                        "instead. 0 turns the check off.");
    }
    prm.leave_subsection();

    prm.enter_subsection("Cavity");
    {
      prm.declare_entry("Lower corner",
                        "0, 0",
                        Patterns::List(Patterns::Double(), 2, 3),
                        "Lower corner of the box-shaped cavity (m).");
      prm.declare_entry("Upper corner",
                        "0.28575, 0.142875",
                        Patterns::List(Patterns::Double(), 2, 3),
                        "Upper corner of the box-shaped cavity (m).");
      prm.declare_entry("Coarse subdivisions",
                        "2, 1",
                        Patterns::List(Patterns::Integer(1), 2, 3),
                        "Number of coarse cells per direction; choose them so "
                        "that coarse cells are roughly cubes. Refinement "
                        "levels count from this mesh.");
    }
    prm.leave_subsection();

    prm.enter_subsection("Walls");
    {
      const std::array<std::string, 6> defaults = {
        {"slip", "slip", "slip", "open", "slip", "open"}};
      for (unsigned int w = 0; w < 6; ++w)
        {
          prm.declare_entry(
            wall_names[w],
            defaults[w],
            Patterns::Selection("no-slip|slip|open|velocity|periodic|contact"),
            "Condition on the cavity wall " + wall_names[w] + " (boundary id " +
              std::to_string(w) +
              "): no-slip (u = 0), slip (u.n = 0, no tangential "
              "stress), open (zero traction), velocity (u given by the "
              "entry '" +
              wall_names[w] +
              " velocity'), periodic (the opposite wall must be "
              "periodic too: the liquid leaving through one wall enters "
              "through the other) or contact (the seed's Signorini-like "
              "wall: the liquid cannot cross it but may leave it, no "
              "tangential stress; the contact force and the contact "
              "length or area go to the statistics). z walls are used in "
              "3D only.");
          prm.declare_entry(wall_names[w] + " velocity",
                            "0; 0",
                            Patterns::Anything(),
                            "Velocity imposed on wall " + wall_names[w] +
                              " when its type is 'velocity': one muParser "
                              "expression per component, separated by ';', "
                              "in x, y, (z,) t.");
        }
    }
    prm.leave_subsection();

    prm.enter_subsection("Material");
    {
      prm.declare_entry("Density",
                        "1000",
                        Patterns::Double(),
                        "Density rho (kg/m^3), positive.");
      prm.declare_entry("Solvent viscosity",
                        "0.001",
                        Patterns::Double(),
                        "Solvent viscosity eta_s (Pa s), non-negative.");
      prm.declare_entry("Polymer viscosity",
                        "0",
                        Patterns::Double(),
                        "Polymer viscosity eta_p (Pa s), non-negative; "
                        "positive in the Oldroyd-B and elastic regimes. In "
                        "the elastic regime the shear modulus is "
                        "G = eta_p / lambda.");
      prm.declare_entry("Relaxation time",
                        "0",
                        Patterns::Double(),
                        "Relaxation time lambda (s). Zero selects the "
                        "Newtonian regime with viscosity eta_s + eta_p; "
                        "positive: the Oldroyd-B liquid (Alpha = 1) or the "
                        "elastic solid (Alpha = 0).");
      prm.declare_entry(
        "Alpha",
        "1",
        Patterns::Integer(0, 1),
        "Factor of sigma in the constitutive law alpha sigma + lambda "
        "(upper-convected derivative of sigma) = 2 eta_p eps(u): 1 for "
        "liquids, 0 for the elastic limit, an incompressible neo-Hookean "
        "solid with sigma = G (B - I), G = eta_p / lambda (needs lambda > 0 "
        "and eta_p > 0). A positive solvent viscosity with Alpha = 0 adds a "
        "viscous stress 2 eta_s eps(u): a Kelvin-Voigt solid.");
    }
    prm.leave_subsection();

    prm.enter_subsection("Initial liquid");
    {
      prm.declare_entry("Shape",
                        "box",
                        Patterns::Selection("box|ball|expression"),
                        "Shape of the liquid at t = 0: a box, a ball, or "
                        "the region where 'Level set expression' < 0.");
      prm.declare_entry(
        "Box lower corner",
        "0, 0",
        Patterns::List(Patterns::Double(), 2, 3),
        "Lower corner of the liquid box (m). A box face on a cavity wall "
        "wets that wall (it is not a free surface).");
      prm.declare_entry("Box upper corner",
                        "0.05715, 0.1143",
                        Patterns::List(Patterns::Double(), 2, 3),
                        "Upper corner of the liquid box (m).");
      prm.declare_entry("Ball center",
                        "0, 0",
                        Patterns::List(Patterns::Double(), 2, 3),
                        "Center of the liquid ball (m).");
      prm.declare_entry("Ball radius",
                        "0.1",
                        Patterns::Double(0),
                        "Radius of the liquid ball (m).");
      prm.declare_entry("Level set expression",
                        "",
                        Patterns::Anything(),
                        "muParser expression in x, y, (z): the liquid is "
                        "where it is negative. It should be close to a "
                        "signed distance (m) near its zero level, and "
                        "smooth: with the gradient augmented transport and "
                        "no redistancing, a kink (the center of "
                        "sqrt(r^2) - R) that the flow carries near the "
                        "surface costs accuracy; (r^2 - R^2) / (2 R) has "
                        "the same zero level and none.");
      prm.declare_entry("Velocity",
                        "0; 0",
                        Patterns::Anything(),
                        "Initial velocity (m/s): one muParser expression "
                        "per component, separated by ';', in x, y, (z). All "
                        "expressions know the constant pi.");
      prm.declare_entry("Stress",
                        "",
                        Patterns::Anything(),
                        "Initial extra stress sigma (Pa) in the Oldroyd-B and "
                        "elastic regimes: muParser expressions in x, y, (z) "
                        "for the components xx; yy; xy (2D) or xx; yy; zz; "
                        "xy; xz; yz (3D). Empty: zero.");
    }
    prm.leave_subsection();

    prm.enter_subsection("Mesh refinement");
    {
      prm.declare_entry("Minimum level",
                        "2",
                        Patterns::Integer(0, 20),
                        "Refinement level of the empty part of the cavity.");
      prm.declare_entry("Bulk level",
                        "4",
                        Patterns::Integer(0, 20),
                        "Refinement level of the liquid away from its free "
                        "surface.");
      prm.declare_entry("Maximum level",
                        "6",
                        Patterns::Integer(0, 20),
                        "Refinement level in the band around the free "
                        "surface.");
      prm.declare_entry("Band width",
                        "4",
                        Patterns::Double(1),
                        "Half width of the finest band around the free "
                        "surface, in finest cells. With 'Band placement = "
                        "widened' the band is widened to CFL + 2 cells (the "
                        "target CFL, or the CFL number of the last step if "
                        "larger) so that the surface cannot leave it within "
                        "a step. Distances are "
                        "estimated as psi / |grad psi| where the level set "
                        "is steeper than a distance.");
      prm.declare_entry(
        "Band placement",
        "widened",
        Patterns::Selection("widened|predicted|predicted, one change"),
        "How the band of finest cells keeps up with a moving surface. "
        "widened: the band is widened by the CFL number, as 'Band width' "
        "says, and the mesh is adapted once per step, after the advection. "
        "predicted: before each advection the level set is traced along the "
        "characteristics on the present mesh (a prediction of where the "
        "surface will be) and the mesh is refined around the present and the "
        "predicted surface; the band stays 'Band width' cells wide at any "
        "CFL number, so large steps no longer fill the mesh with fine cells, "
        "at the cost of one more trace and a few more adaptation cycles per "
        "step. Cells within a step's local motion of the predicted surface "
        "(and two finest cells more) are brought one level below the finest, "
        "so that the next step's refinement takes one cycle there. "
        "predicted, one change: as predicted, but the change before the "
        "advection also coarsens the band of the present surface, which "
        "the next mesh change would otherwise coarsen after the advection: "
        "the advection reads the coarsened cells' fields at their former "
        "children's vertices (kept for it), and the mesh changes once per "
        "step instead of twice, again after the advection only where the "
        "surface left the finest cells. Needs linear interpolation at the "
        "feet (Level set, Velocity and Stress interpolation). "
        "Both predicted placements need 'Remap distance = 0'.");
      prm.declare_entry(
        "Band miss tolerance",
        "0",
        Patterns::Double(0, 1),
        "With 'Band placement = predicted, one change': the fraction of the "
        "cells the surface crosses after the advection that may be coarser "
        "than the finest level (the surface left the band there) before the "
        "mesh changes again after the advection. Each change rebuilds the "
        "whole mesh; up to this fraction, the flow step cuts those cells on "
        "their coarser level and the next step's change before the advection "
        "refines them. 0: the mesh changes whenever one cell is left "
        "coarse.");
      prm.declare_entry(
        "Flow cells",
        "finest",
        Patterns::Selection("finest|parents"),
        "The cells of the flow's velocity and pressure. finest: every cell. "
        "parents: where the mesh is at 'Maximum level', the flow's unknowns "
        "are Q1 on the parents of the finest cells, one level coarser than "
        "the transport (as the seed's 5 mm flow cells over 1 mm transport "
        "cells), while the liquid domain is still cut out of the finest "
        "cells. About 2^dim times fewer flow unknowns in the band around the "
        "surface. Needs 'Bulk level' = 'Maximum level' - 1; not with "
        "periodic walls.");
      prm.declare_entry("Extension layers",
                        "4",
                        Patterns::Integer(1, 100),
                        "Number of cell layers beyond the liquid into which "
                        "the velocity is extended for the characteristics; "
                        "at least CFL + 2 layers are used, as for the "
                        "band.");
      prm.declare_entry(
        "Outside velocity of cut cells",
        "solution",
        Patterns::Selection("solution|extension"),
        "The velocity that the characteristics see at the vertices of cut "
        "cells that lie outside the liquid (psi > 0): solution (the flow "
        "step's, which its elements extrapolate smoothly: best for liquids; "
        "with extension the standing wave's frequency error goes from 0.74 % "
        "to -0.84 % and its amplitude from a 2.2 % loss to a 5.2 % gain per "
        "period, the broken dam's largest height error from 0.031 to 0.039) "
        "or extension (the average of the liquid nodes around, as in the "
        "extension layers beyond). Where a free surface meets a no-slip "
        "wall, only the ghost penalty and a sliver of liquid set the "
        "solution there, and in an elastic body held by that wall it feeds "
        "a growing local mode: the 3D beam of prm/oscillating_beam.prm "
        "stalls at t = 0.17 s with solution and runs to the end with "
        "extension (doc/bouncing_ball.md). The stress at these vertices: "
        "'Outside stress of cut cells'.");
      prm.declare_entry(
        "Outside stress of cut cells",
        "updated",
        Patterns::Selection("updated|extension"),
        "The stress at the vertices of cut cells that lie outside the liquid "
        "(psi > 0): updated (the stress update carries it by the cut cell's "
        "mean velocity gradient, bounded by 10 times the stretch of the "
        "cell's liquid nodes) or extension (the average of the liquid nodes "
        "around, as in the extension layers beyond). Nothing in the flow "
        "step resists the stretching of these vertices, and their stress "
        "enters the liquid through the Q1 interpolation: with 'updated' "
        "this is a source of energy. It shows once the scheme stops damping "
        "('Solver/Stress theta' = 0.5): the 2D stiff ball resting on the "
        "floor after its second contact gained 31.5 J/m in 0.15 s with "
        "updated and lost 0.9 J/m with extension "
        "(doc/bouncing_ball.md).");
      prm.declare_entry("Redistancing interval",
                        "1",
                        Patterns::Integer(0),
                        "Every this many steps, make the level set a signed "
                        "distance again away from the surface (the surface "
                        "itself does not move); 0: never. The distance has "
                        "kinks (between two surfaces) that the cubic "
                        "interpolations smear: with the gradient augmented "
                        "level set, which carries its own gradient, 0 is "
                        "more accurate for transport.");
      prm.declare_entry(
        "Remap distance",
        "0",
        Patterns::Double(0),
        "In finest cells: 0 interpolates the level set at the feet of the "
        "characteristics at every step and adapts the mesh at every step. A "
        "positive value does both only once the surface has moved about this "
        "far since the last time (a remap); in between, the level set of a "
        "step is the remapped one seen through the characteristics of all "
        "the steps since (each traced in the velocity of its own step), so "
        "short steps add no interpolation error and the shape error no "
        "longer grows as the steps shrink (Rider-Kothe vortex at h = 1/128, "
        "CFL 1, without volume correction: L1 error 4.6e-3 with 0, 4.0e-4 "
        "with 10; doc/transport.md). The fine band is widened to this many "
        "cells. Redistancing (at its interval) is done at remaps only. "
        "Checkpoints hold the steps since the last remap.");
      prm.declare_entry("Level set interpolation",
                        "linear",
                        Patterns::Selection(
                          "linear|cubic|limited cubic|gradient augmented"),
                        "How the level set is interpolated at the feet of "
                        "the characteristics: linear (Q1, an O(h^2) error "
                        "per step, so the surface smears as the steps "
                        "shrink); cubic (tensor-product cubic Hermite with "
                        "nodal derivatives recovered from the Q1 field); "
                        "limited cubic (cubic clipped to the range of the "
                        "cell's nodal values); gradient augmented (cubic "
                        "Hermite with the gradient of the level set carried "
                        "along the characteristics as well, Nave, Rosales & "
                        "Seibold 2010, with a four-stage trace of the feet; "
                        "9x smaller L1 error on the Rider-Kothe vortex at "
                        "h = 1/128, CFL 5; the default stays linear because "
                        "the broken dam tests' outputs change, within their "
                        "bounds, see doc/transport.md).");
      prm.declare_entry(
        "Velocity interpolation",
        "linear",
        Patterns::Selection("linear|cubic|limited cubic"),
        "How the velocity is interpolated at the feet of the "
        "characteristics: linear (Q1), which damps a velocity field that "
        "varies within a few cells (its error acts as a viscosity of order "
        "h |u|); cubic (tensor-product cubic Hermite with nodal derivatives "
        "recovered from the Q1 field); limited cubic (cubic clipped to the "
        "range of the cell's nodal values: no new extrema). Measured on the "
        "2D stiff ball in doc/bouncing_ball.md.");
      prm.declare_entry(
        "Stress interpolation",
        "linear",
        Patterns::Selection("linear|limited cubic"),
        "How the stress is interpolated at the feet of the characteristics: "
        "linear (Q1: a convex combination, so the conformation tensor c = "
        "I + lambda sigma / eta_p stays positive definite, but an elastic "
        "body's stress is damped as its velocity is by linear velocity "
        "interpolation) or limited cubic (each component by limited cubic "
        "Hermite interpolation, kept only where the smallest eigenvalue of "
        "c is at least half that of the linear one, else linear; "
        "unsafeguarded, the 2D stiff ball lost positive definiteness at the "
        "impact and blew up). Measured on the 2D stiff ball in "
        "doc/bouncing_ball.md.");
      prm.declare_entry("Volume correction",
                        "true",
                        Patterns::Bool(),
                        "Restore the initial liquid volume after each "
                        "advection by a uniform normal shift of the free "
                        "surface.");
    }
    prm.leave_subsection();

    prm.enter_subsection("Solver");
    {
      prm.declare_entry("Tolerance",
                        "1e-8",
                        Patterns::Double(0, 1),
                        "Relative residual reduction of the Krylov solver.");
      prm.declare_entry(
        "Contact tolerance",
        "1e-4",
        Patterns::Double(0, 1),
        "With contact walls: the relative residual reduction of the solves "
        "while the contact set still changes. They only have to tell which "
        "nodes touch; once a solve leaves the set unchanged the step is "
        "solved again, from there, to 'Tolerance' (and the set checked "
        "again). At or below 'Tolerance': every contact iteration is solved "
        "fully.");
      prm.declare_entry("Maximum iterations",
                        "1000",
                        Patterns::Integer(1),
                        "Iterations after which the Krylov solver gives up "
                        "and stops the run.");
      prm.declare_entry("AMG smoother sweeps",
                        "4",
                        Patterns::Integer(1, 20),
                        "Smoother sweeps per level of the AMG V-cycles for "
                        "the velocity block and for the pressure Laplacian "
                        "of the Schur approximation. The velocity block is "
                        "dominated by the mass matrix rho/tau M when "
                        "rho h^2/(tau mu) is large, and then the smoother does "
                        "most of the work: 4 keeps the iteration counts flat "
                        "under refinement (measured: 2D broken dam, levels "
                        "5-9; 3D; doc/broken_dam.md).");
      prm.declare_entry(
        "Pressure stabilization",
        "0.25",
        Patterns::Double(0),
        "Factor c of the PSPG parameter of the Q1-Q1 "
        "element, tau_K = c / (rho/tau + 4 mu / h_K^2). "
        "Its consistency error grows with c where the "
        "pressure gradient is large: the stiff ball's "
        "lift-off and rebound only settled under refinement "
        "with 0.05 (its scene's value; 10-20 % more Krylov "
        "iterations at 0.02-0.01; doc/bouncing_ball.md).");
      prm.declare_entry(
        "Free surface stabilization",
        "0",
        Patterns::Double(0, 1),
        "Factor theta in [0, 1] of the free-surface stabilisation (Kaus et "
        "al., PEPI 181, 2010; ASPECT's free surface stabilization theta): "
        "the flow step sees the hydrostatic load change of the surface "
        "moving by tau u.n within the step, theta tau rho |g.n| (u.n)(v.n) "
        "on the free surface where gravity presses it back. 0: the surface "
        "is explicit, stable for tau below about 2 (h / (pi |g|))^(1/2), h "
        "the finest cell (0.010 s at h = 0.8 mm); 0.5 removes that limit "
        "but damps surface waves of frequency omega by about "
        "exp(-pi omega tau / 2) per period (see doc/standing_wave.md).");
      prm.declare_entry(
        "Stress update",
        "linear",
        Patterns::Selection("linear|exponential"),
        "How the conformation tensor c (B for the elastic solid) is carried "
        "by the new velocity gradient L after the diffusion step: linear, "
        "c* + tau (L c* + c* L^T), the seed's first-order formula and the "
        "one the diffusion step sees, which loses positive definiteness "
        "once tau |L| is of order one (an impact); exponential, exp(tau L) "
        "c* exp(tau L)^T, the exact solution for a velocity gradient "
        "constant over the step, positive definite by construction and "
        "equal to the linear one to first order. The relaxation (alpha > 0) "
        "follows in both cases.");
      prm.declare_entry(
        "Stress theta",
        "1",
        Patterns::Double(0.5, 1),
        "Weight theta in [0.5, 1] of the new velocity u in the stress of "
        "the diffusion step: the stress law sees theta u + (1 - theta) u* "
        "(u* the advected velocity) and the momentum equation the stress "
        "theta sigma^{n+1} + (1 - theta) sigma*. 1: the seed's backward "
        "Euler, which damps elastic oscillations (first order in tau); 0.5: "
        "the midpoint rule, which keeps the energy of a linear elastic "
        "oscillation. No effect on Newtonian liquids. See "
        "doc/bouncing_ball.md.");
      prm.declare_entry("Ghost penalty",
                        "0.1",
                        Patterns::Double(0),
                        "Factor gamma of the ghost penalty on the faces of "
                        "cells cut by the free surface (see doc/method.md): "
                        "it keeps a cell with a small liquid part as well "
                        "conditioned as a whole one. 0 switches it off.");
    }
    prm.leave_subsection();

    prm.enter_subsection("Transport");
    {
      prm.declare_entry("Prescribed velocity",
                        "",
                        Patterns::Anything(),
                        "If not empty, the velocity is this muParser "
                        "expression (one per component, separated by ';', "
                        "in x, y, (z,) t) instead of the solution of the "
                        "flow equations, which are then not solved: a mode "
                        "to test the transport of the free surface alone.");
      prm.declare_entry("Exact final level set",
                        "",
                        Patterns::Anything(),
                        "If not empty, the exact liquid region at the end "
                        "time, to measure the shape error: 'initial' (the "
                        "flow brings the liquid back to its initial shape) "
                        "or a muParser expression in x, y, (z) negative in "
                        "the liquid. Adds the columns shape_error and "
                        "interface_thickness to the statistics.");
    }
    prm.leave_subsection();

    prm.enter_subsection("Postprocess");
    {
      prm.declare_entry("Probe point",
                        "",
                        Patterns::List(Patterns::Double(), 0, 3),
                        "If not empty, a point (m) of the cavity where the "
                        "velocity is written to the statistics every step "
                        "(columns probe_u_x, probe_u_y, probe_u_z).");
    }
    prm.leave_subsection();

    prm.enter_subsection("Checkpoint");
    {
      prm.declare_entry("Interval steps",
                        "0",
                        Patterns::Integer(0),
                        "Write a checkpoint (mesh, fields, time and "
                        "statistics position, into <Output directory>/"
                        "checkpoint) after every step whose number is a "
                        "multiple of this; 0: never. A run continues from "
                        "its last checkpoint with 'vefs --resume <Output "
                        "directory>', also on another number of MPI ranks.");
      prm.declare_entry("Interval minutes",
                        "60",
                        Patterns::Double(0),
                        "Also write a checkpoint after the step that ends "
                        "this many minutes of wall time after the start (or "
                        "the last checkpoint); 0: never. A SIGTERM or SIGINT "
                        "always writes one after the current step.");
      prm.declare_entry("Stop after steps",
                        "0",
                        Patterns::Integer(0),
                        "If positive: after this many steps of this "
                        "invocation (counted from the start or from the "
                        "resumed step), write a checkpoint and stop with "
                        "exit status 0 (for jobs with a wall-time limit: "
                        "each job resumes the last one and does this many "
                        "steps); 0: run to the end time.");
    }
    prm.leave_subsection();

    prm.enter_subsection("Output");
    {
      prm.declare_entry("Interval",
                        "10",
                        Patterns::Integer(0),
                        "Write visualization files every this many time "
                        "steps (and at the first and last step); 0 writes "
                        "none.");
      prm.declare_entry("Time interval",
                        "0",
                        Patterns::Double(0),
                        "If positive, write visualization files at the "
                        "multiples of this time instead (the time step is "
                        "shortened to land on them): with an adaptive time "
                        "step, the frames of a scene then show the same "
                        "instants whatever the resolution.");
      prm.declare_entry("Verbose",
                        "true",
                        Patterns::Bool(),
                        "Print a progress line per time step and a timing "
                        "summary at the end.");
    }
    prm.leave_subsection();
  }

  void
  Parameters::parse(ParameterHandler &prm)
  {
    dimension        = prm.get_integer("Dimension");
    output_directory = prm.get("Output directory");
    gravity          = to_doubles(prm.get("Gravity"));

    prm.enter_subsection("Time");
    end_time                   = prm.get_double("End time");
    time_step                  = prm.get_double("Time step");
    target_cfl                 = prm.get_double("Target CFL");
    max_strain_per_step        = prm.get_double("Maximum strain per step");
    strain_bound_shortens_step = prm.get("Strain bound") == "step";
    maximum_steps              = prm.get_integer("Maximum steps");
    prm.leave_subsection();

    prm.enter_subsection("Health check");
    max_volume_change      = prm.get_double("Maximum volume change");
    max_cfl                = prm.get_double("Maximum CFL");
    min_time_step_fraction = prm.get_double("Minimum time step fraction");
    prm.leave_subsection();

    prm.enter_subsection("Cavity");
    cavity_lower = to_doubles(prm.get("Lower corner"));
    cavity_upper = to_doubles(prm.get("Upper corner"));
    coarse_subdivisions.clear();
    for (const int n : Utilities::string_to_int(
           Utilities::split_string_list(prm.get("Coarse subdivisions"), ',')))
      coarse_subdivisions.push_back(n);
    prm.leave_subsection();

    prm.enter_subsection("Walls");
    for (unsigned int w = 0; w < 6; ++w)
      {
        wall_type[w]     = wall_type_names.at(prm.get(wall_names[w]));
        wall_velocity[w] = prm.get(wall_names[w] + " velocity");
      }
    prm.leave_subsection();

    prm.enter_subsection("Material");
    density           = prm.get_double("Density");
    solvent_viscosity = prm.get_double("Solvent viscosity");
    polymer_viscosity = prm.get_double("Polymer viscosity");
    relaxation_time   = prm.get_double("Relaxation time");
    alpha             = prm.get_integer("Alpha");
    prm.leave_subsection();

    prm.enter_subsection("Initial liquid");
    initial_shape        = prm.get("Shape");
    box_lower            = to_doubles(prm.get("Box lower corner"));
    box_upper            = to_doubles(prm.get("Box upper corner"));
    ball_center          = to_doubles(prm.get("Ball center"));
    ball_radius          = prm.get_double("Ball radius");
    level_set_expression = prm.get("Level set expression");
    initial_velocity     = prm.get("Velocity");
    initial_stress       = prm.get("Stress");
    prm.leave_subsection();

    prm.enter_subsection("Mesh refinement");
    min_level           = prm.get_integer("Minimum level");
    bulk_level          = prm.get_integer("Bulk level");
    max_level           = prm.get_integer("Maximum level");
    band_width          = prm.get_double("Band width");
    band_predicted      = prm.get("Band placement") != "widened";
    band_in_one_change  = prm.get("Band placement") == "predicted, one change";
    band_miss_tolerance = prm.get_double("Band miss tolerance");
    extension_layers    = prm.get_integer("Extension layers");
    flow_on_parents     = prm.get("Flow cells") == "parents";
    extend_outside_velocity =
      prm.get("Outside velocity of cut cells") == "extension";
    extend_outside_stress =
      prm.get("Outside stress of cut cells") == "extension";
    volume_correction     = prm.get_bool("Volume correction");
    redistancing_interval = prm.get_integer("Redistancing interval");
    remap_distance        = prm.get_double("Remap distance");
    {
      const std::string name  = prm.get("Level set interpolation");
      level_set_interpolation = name == "linear" ? LevelSetInterpolation::linear
                                : name == "cubic" ? LevelSetInterpolation::cubic
                                : name == "limited cubic"
                                  ? LevelSetInterpolation::limited_cubic
                                  : LevelSetInterpolation::gradient_augmented;
    }
    cubic_stress_interpolation =
      prm.get("Stress interpolation") == "limited cubic";
    {
      const std::string name = prm.get("Velocity interpolation");
      velocity_interpolation = name == "linear" ? VelocityInterpolation::linear
                               : name == "cubic"
                                 ? VelocityInterpolation::cubic
                                 : VelocityInterpolation::limited_cubic;
    }
    prm.leave_subsection();

    prm.enter_subsection("Solver");
    solver_tolerance           = prm.get_double("Tolerance");
    contact_solver_tolerance   = prm.get_double("Contact tolerance");
    solver_max_iterations      = prm.get_integer("Maximum iterations");
    pressure_stabilization     = prm.get_double("Pressure stabilization");
    ghost_penalty              = prm.get_double("Ghost penalty");
    free_surface_stabilization = prm.get_double("Free surface stabilization");
    stress_update              = prm.get("Stress update") == "linear"
                                   ? StressUpdate::linear
                                   : StressUpdate::exponential;
    stress_theta               = prm.get_double("Stress theta");
    amg_smoother_sweeps        = prm.get_integer("AMG smoother sweeps");
    prm.leave_subsection();

    prm.enter_subsection("Transport");
    prescribed_velocity   = prm.get("Prescribed velocity");
    exact_final_level_set = prm.get("Exact final level set");
    prm.leave_subsection();

    prm.enter_subsection("Postprocess");
    probe_point = to_doubles(prm.get("Probe point"));
    prm.leave_subsection();

    prm.enter_subsection("Checkpoint");
    checkpoint_interval_steps   = prm.get_integer("Interval steps");
    checkpoint_interval_minutes = prm.get_double("Interval minutes");
    stop_after_steps            = prm.get_integer("Stop after steps");
    prm.leave_subsection();

    prm.enter_subsection("Output");
    output_interval      = prm.get_integer("Interval");
    output_time_interval = prm.get_double("Time interval");
    verbose              = prm.get_bool("Verbose");
    prm.leave_subsection();

    check();
  }

  void
  Parameters::check_for_ranks(const unsigned int n_ranks) const
  {
    const auto periodic = periodic_directions();
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

  std::vector<unsigned int>
  Parameters::periodic_directions() const
  {
    std::vector<unsigned int> directions;
    for (unsigned int d = 0; d < dimension; ++d)
      if (wall_type[2 * d] == WallType::periodic)
        directions.push_back(d);
    return directions;
  }

  Regime
  Parameters::regime() const
  {
    if (relaxation_time == 0)
      return Regime::newtonian;
    return alpha == 1 ? Regime::oldroyd_b : Regime::elastic_solid;
  }

  void
  Parameters::check()
  {
    warnings.clear();
    const std::string dim_text      = std::to_string(dimension);
    auto              require_point = [&](const std::vector<double> &p,
                             const std::string         &entry) {
      require(p.size() == dimension,
              entry,
              "needs " + dim_text + " comma-separated numbers (Dimension = " +
                dim_text + "), got " + std::to_string(p.size()));
    };

    require_point(gravity, "Gravity");
    require(end_time > 0, "Time/End time", "must be positive");
    require(time_step > 0, "Time/Time step", "must be positive");

    require_point(cavity_lower, "Cavity/Lower corner");
    require_point(cavity_upper, "Cavity/Upper corner");
    require(coarse_subdivisions.size() == dimension,
            "Cavity/Coarse subdivisions",
            "needs " + dim_text + " comma-separated integers");
    for (unsigned int d = 0; d < dimension; ++d)
      require(cavity_lower[d] < cavity_upper[d],
              "Cavity/Upper corner",
              "must exceed 'Cavity/Lower corner' in every coordinate");

    require(density > 0, "Material/Density", "must be positive");
    require(solvent_viscosity >= 0,
            "Material/Solvent viscosity",
            "must be non-negative");
    require(polymer_viscosity >= 0,
            "Material/Polymer viscosity",
            "must be non-negative");
    require(relaxation_time >= 0,
            "Material/Relaxation time",
            "must be non-negative");
    require(!(alpha == 0 && relaxation_time == 0),
            "Material/Alpha",
            "alpha = 0 (elastic solid) needs a positive relaxation time");
    require(newtonian_viscosity() > 0 || relaxation_time > 0,
            "Material/Solvent viscosity",
            "a Newtonian liquid needs eta_s + eta_p > 0");
    require(regime() == Regime::newtonian || polymer_viscosity > 0,
            "Material/Polymer viscosity",
            std::string(regime() == Regime::elastic_solid
                          ? "alpha = 0 (elastic solid)"
                          : "a positive relaxation time (Oldroyd-B)") +
              " needs a positive polymer viscosity (the shear modulus is "
              "eta_p / lambda)");
    require(regime() != Regime::newtonian || initial_stress.empty(),
            "Initial liquid/Stress",
            "a Newtonian liquid (relaxation time 0) has no extra stress; "
            "leave it empty or give a positive relaxation time");
    require(!velocity_is_prescribed() || initial_stress.empty(),
            "Initial liquid/Stress",
            "with a prescribed velocity the flow (and its stress) is not "
            "solved; leave it empty");
    for (unsigned int d = 0; d < dimension; ++d)
      require((wall_type[2 * d] == WallType::periodic) ==
                (wall_type[2 * d + 1] == WallType::periodic),
              "Walls/" + wall_names[2 * d + 1],
              "walls " + wall_names[2 * d] + " and " + wall_names[2 * d + 1] +
                " are periodic together or not at all");
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
    // A 2D scene has no z walls: an entry there cannot mean anything.
    if (dimension == 2)
      for (unsigned int w = 4; w < 6; ++w)
        {
          const auto compact = [](std::string text) {
            text.erase(std::remove_if(text.begin(),
                                      text.end(),
                                      [](const char c) {
                                        return std::isspace(
                                          static_cast<unsigned char>(c));
                                      }),
                       text.end());
            return text;
          };
          require(compact(wall_velocity[w]) == "0;0",
                  "Walls/" + wall_names[w] + " velocity",
                  "a 2D scene (Dimension = 2) has no z walls; remove the "
                  "entry");
          require(wall_type[w] == (w == 4 ? WallType::slip : WallType::open),
                  "Walls/" + wall_names[w],
                  "a 2D scene (Dimension = 2) has no z walls; remove the "
                  "entry");
        }
    require(probe_point.empty() || probe_point.size() == dimension,
            "Postprocess/Probe point",
            "needs " + dim_text + " comma-separated numbers or nothing");
    for (unsigned int d = 0; d < probe_point.size(); ++d)
      require(probe_point[d] >= cavity_lower[d] &&
                probe_point[d] <= cavity_upper[d],
              "Postprocess/Probe point",
              "must lie inside the cavity");

    if (initial_shape == "box")
      {
        require_point(box_lower, "Initial liquid/Box lower corner");
        require_point(box_upper, "Initial liquid/Box upper corner");
        for (unsigned int d = 0; d < dimension; ++d)
          require(box_lower[d] < box_upper[d],
                  "Initial liquid/Box upper corner",
                  "must exceed 'Box lower corner' in every coordinate");
        for (unsigned int d = 0; d < dimension; ++d)
          require(box_lower[d] < cavity_upper[d] &&
                    box_upper[d] > cavity_lower[d],
                  "Initial liquid/Box upper corner",
                  "the liquid box lies outside the cavity");
        for (unsigned int d = 0; d < dimension; ++d)
          if (box_lower[d] < cavity_lower[d] || box_upper[d] > cavity_upper[d])
            {
              warnings.push_back(
                entry_error("Initial liquid/Box upper corner",
                            "the liquid box reaches beyond the cavity; only "
                            "its part inside the cavity is liquid"));
              break;
            }
      }
    else if (initial_shape == "ball")
      {
        require_point(ball_center, "Initial liquid/Ball center");
        require(ball_radius > 0,
                "Initial liquid/Ball radius",
                "must be positive");
        for (unsigned int d = 0; d < dimension; ++d)
          if (ball_center[d] - ball_radius < cavity_lower[d] ||
              ball_center[d] + ball_radius > cavity_upper[d])
            {
              warnings.push_back(
                entry_error("Initial liquid/Ball radius",
                            "the liquid ball reaches beyond the cavity; only "
                            "its part inside the cavity is liquid"));
              break;
            }
      }

    require(strain_bound_shortens_step ||
              (stress_update == StressUpdate::exponential &&
               max_strain_per_step > 0),
            "Time/Strain bound",
            "'local' scales the strain down in the exponential stress update "
            "only: it needs 'Solver/Stress update = exponential' and a "
            "positive 'Time/Maximum strain per step'");
    require(!band_predicted || remap_distance == 0,
            "Mesh refinement/Band placement",
            "'predicted' adapts the mesh before every advection; between "
            "remaps the mesh stays: it needs 'Mesh refinement/Remap "
            "distance = 0'");
    require(!band_in_one_change ||
              (level_set_interpolation == LevelSetInterpolation::linear &&
               velocity_interpolation == VelocityInterpolation::linear &&
               !cubic_stress_interpolation),
            "Mesh refinement/Band placement",
            "'predicted, one change' keeps the Q1 fields of the coarsened "
            "cells only: it needs 'linear' for 'Level set interpolation', "
            "'Velocity interpolation' and 'Stress interpolation' (in 'Mesh "
            "refinement')");
    require(band_miss_tolerance == 0 || band_in_one_change,
            "Mesh refinement/Band miss tolerance",
            "applies to 'Band placement = predicted, one change' only (the "
            "other placements adapt the mesh after every advection): leave "
            "it 0 or choose that placement");
    require(!flow_on_parents || periodic_directions().empty(),
            "Mesh refinement/Flow cells",
            "'parents' is not implemented with periodic walls: use "
            "'finest'");
    require(!flow_on_parents || (max_level > 0 && bulk_level + 1 >= max_level),
            "Mesh refinement/Flow cells",
            "'parents' needs 'Bulk level' = 'Maximum level' - 1 (or equal to "
            "it, and at least 1): the flow's cells then all lie on one "
            "level");
    require(min_level <= bulk_level && bulk_level <= max_level,
            "Mesh refinement/Bulk level",
            "levels must satisfy Minimum level <= Bulk level <= Maximum "
            "level");

    check_resources(*this);

    if (dimension == 2)
      check_expressions<2>(*this);
    else
      check_expressions<3>(*this);
  }
} // namespace vefs
