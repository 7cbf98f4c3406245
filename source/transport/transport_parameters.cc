#include <vefs/base/parameter_entries.h>
#include <vefs/transport/transport_parameters.h>

namespace vefs
{
  using namespace dealii;

  void
  TransportParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Transport");
    {
      add_selection(prm,
                    "Level set interpolation",
                    level_set_interpolation,
                    std::vector<std::pair<std::string, LevelSetInterpolation>>{
                      {"automatic", LevelSetInterpolation::automatic},
                      {"linear", LevelSetInterpolation::linear},
                      {"gradient augmented",
                       LevelSetInterpolation::gradient_augmented}},
                    "How the level set is interpolated at the feet of "
                    "the characteristics: linear (Q1, an O(h^2) error "
                    "per step, so the surface smears as the steps "
                    "shrink) or gradient augmented (cubic Hermite with "
                    "the gradient of the level set carried along the "
                    "characteristics as well, Nave, Rosales & Seibold "
                    "2010, with a four-stage trace of the feet). "
                    "Rider-Kothe vortex from a signed distance at h = "
                    "1/128, CFL 5: L1 error 3.0e-2 with linear, 5.9e-4 "
                    "with gradient augmented for 1.5 times the CPU time "
                    "(doc/transport.md). automatic: gradient augmented "
                    "in 2D and for a prescribed velocity (a falling drop "
                    "keeps its area to 0.2 % instead of 7.8 %, test "
                    "drop_into_pool_2d), linear for a 3D flow (there "
                    "gradient augmented took 1.08-1.63 times the wall "
                    "time, was no closer to the 3D dam's reference and "
                    "left the soft 3D ball and beam less of their energy) "
                    "and with 'Band placement = predicted, one change'; "
                    "see doc/transport_in_flows.md.");
      add_selection(
        prm,
        "Velocity interpolation",
        velocity_interpolation,
        std::vector<std::pair<std::string, VelocityInterpolation>>{
          {"automatic", VelocityInterpolation::automatic},
          {"linear", VelocityInterpolation::linear},
          {"cubic", VelocityInterpolation::cubic},
          {"limited cubic", VelocityInterpolation::limited_cubic}},
        "How the velocity is interpolated at the feet of the "
        "characteristics: linear (Q1), which damps a velocity field that "
        "varies within a few cells (its error acts as a viscosity of order "
        "h |u|); cubic (tensor-product cubic Hermite with nodal derivatives "
        "recovered from the Q1 field); limited cubic (cubic clipped to the "
        "range of the cell's nodal values: no new extrema); the second-order "
        "scheme's acceleration is interpolated the same way. automatic: "
        "cubic for a stiff elastic solid under gravity (alpha = 0, "
        "macroscopic stress, the second-order scheme, rho |g| L / (3 G) < 1 "
        "with L the cavity's largest extent: its weight strains no body in "
        "the cavity by 1), linear otherwise. Measured (doc/bouncing_ball.md): "
        "the 2D stiff ball's first contact loses 24.5 % of its kinetic "
        "energy at impact with it, 25.4 % with limited cubic, and keeps 83 % "
        "of its energy by lift-off with linear against 92 % with limited "
        "cubic; the stiff beam at rest keeps its energy; the soft "
        "3D ball stops with it (Stokes solver not converging), the soft 3D "
        "beam's solves need three times the default 'Solver/Maximum "
        "iterations' and the soft 2D ball takes 1.8 times the steps. Linear "
        "also for liquids, dumbbells, the first-order scheme and scenes "
        "without gravity (the seed's splitting and the shear wave, measured "
        "with it in doc/viscoelastic.md), and with 'Mesh refinement/Band "
        "placement = predicted, one change', which keeps Q1 fields only.");
      add_selection(
        prm,
        "Stress interpolation",
        stress_interpolation,
        std::vector<std::pair<std::string, StressInterpolation>>{
          {"automatic", StressInterpolation::automatic},
          {"linear", StressInterpolation::linear},
          {"limited cubic", StressInterpolation::limited_cubic}},
        "How the stress is interpolated at the feet of the characteristics: "
        "linear (Q1: a convex combination, so the conformation tensor c = "
        "I + lambda sigma / eta_p stays positive definite, but an elastic "
        "body's stress is damped as its velocity is by linear velocity "
        "interpolation) or limited cubic (each component by limited cubic "
        "Hermite interpolation, kept only where the smallest eigenvalue of "
        "c is at least half that of the linear one, else linear; "
        "unsafeguarded, the 2D stiff ball lost positive definiteness at the "
        "impact and blew up). automatic: limited cubic where 'Velocity "
        "interpolation' is cubic or limited cubic, linear otherwise: an "
        "elastic wave carries its energy in both fields, and the 2D stiff "
        "ball kept 92 % of its energy by lift-off with both limited cubic, "
        "87 % and 86 % with one of them, 83 % with neither (doc/"
        "bouncing_ball.md).");
      add_number_or_automatic(
        prm,
        "Transport",
        "Remap distance",
        remap_distance,
        automatic_remap_distance,
        0,
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
        "cells. Redistancing (at its interval) is done at remaps only, "
        "and in 2D leaves the level set within twice this distance of the "
        "surface as transported: the characteristics of the next remaps "
        "read it there, and a distance has kinks inside thin filaments. "
        "Checkpoints hold the steps since the last remap. automatic: for "
        "the gradient augmented level set carried by a 'Prescribed "
        "velocity' (the transport benchmarks), 20 in 2D (Rider-Kothe vortex "
        "from a signed distance at 1/128, CFL 5: L1 6.7e-4 with 20, 1.35e-3 "
        "with 10, 2.8e-3 with 10 and the distance restored up to the cut "
        "cells) and 14 in 3D (the 3D deformation at 1/128, CFL 5: relative "
        "L1 0.0155 with 14, 0.0172 with 10, for 1.5 times the CPU time; at "
        "1/64 0.039 with 14, 0.106 with 16); 0 otherwise: with "
        "the linear level set the volume correction then misses at remap "
        "steps; in flows the mesh, adapted at remaps only, carries a band "
        "R cells wide for the flow too (R = 20: the 2D flow tests took "
        "1.5-3.4 times the CPU time, the stiff ball's Stokes solver "
        "stopped at the impact, the oscillating beam's energy rose; "
        "doc/transport_in_flows.md); and both predicted band placements "
        "adapt the mesh at every step.");
      prm.add_parameter("Redistancing interval",
                        redistancing_interval,
                        "Every this many steps, make the level set a signed "
                        "distance again away from the surface (the surface "
                        "itself does not move; with a 'Remap distance' R, "
                        "at remaps, and in 2D beyond 2R finest cells from "
                        "the surface); 0: never. The distance has kinks "
                        "(between two surfaces) that the cubic "
                        "interpolations smear.",
                        Patterns::Integer(0));
      prm.add_parameter("Volume correction",
                        volume_correction,
                        "Restore the initial liquid volume after each "
                        "advection by moving the free surface along its "
                        "normal ('Volume correction shift' says how).",
                        Patterns::Bool());
      add_selection(
        prm,
        "Volume correction shift",
        volume_correction_shift,
        std::vector<std::pair<std::string, ShiftWeight>>{
          {"uniform", ShiftWeight::uniform},
          {"surface speed", ShiftWeight::surface_speed}},
        "How the volume correction moves the surface: uniform (the whole "
        "surface by the same distance along its normal) or surface speed "
        "(each node of the level set in proportion to its speed over the "
        "largest speed on the surface, at least 0.05 of it: where the "
        "surface rests the characteristics end at the nodes and make no "
        "volume error, so the correction goes where the surface moves). "
        "Measured (doc/volume_correction.md): surface speed takes the 2D "
        "dam's height error from 0.036 to 0.034 and the falling drop's area "
        "change from -0.24 % to -0.067 % and keeps the standing wave, but a "
        "pool at rest whose surface lies on mesh nodes then moves (its floor "
        "pressure 1.2 % below hydrostatic after 0.12 s), the soft 2D ball "
        "loses 18 J/m from its first contact on against 16 J/m and the stiff "
        "ball's first contact 3.9 % at 1.56 mm against 2.0 % (10.0 / 4.0 % "
        "against 10.9 / 4.2 % at 6.25 / 3.12 mm): uniform is the default. It "
        "needs 'Remap distance = 0': between remaps the level set is the "
        "remapped one seen through the characteristics, which carry a "
        "uniform shift but not a field.");
      prm.add_parameter("Prescribed velocity",
                        prescribed_velocity,
                        "If not empty, the velocity is this muParser "
                        "expression (one per component, separated by ';', "
                        "in x, y, (z,) t) instead of the solution of the "
                        "flow equations, which are then not solved: a mode "
                        "to test the transport of the free surface alone.",
                        Patterns::Anything());
      prm.add_parameter("Exact final level set",
                        exact_final_level_set,
                        "If not empty, the exact liquid region at the end "
                        "time, to measure the shape error: 'initial' (the "
                        "flow brings the liquid back to its initial shape) "
                        "or a muParser expression in x, y, (z) negative in "
                        "the liquid. Adds the columns shape_error and "
                        "interface_thickness to the statistics.",
                        Patterns::Anything());
    }
    prm.leave_subsection();
  }

  void
  TransportParameters::resolve_level_set(const unsigned int dimension,
                                         const bool band_in_one_change_set)
  {
    if (level_set_interpolation == LevelSetInterpolation::automatic)
      level_set_interpolation =
        (dimension == 2 || velocity_is_prescribed()) && !band_in_one_change_set
          ? LevelSetInterpolation::gradient_augmented
          : LevelSetInterpolation::linear;
  }

  void
  TransportParameters::resolve(const bool         band_predicted,
                               const bool         band_in_one_change,
                               const bool         stiff_solid,
                               const unsigned int dimension)
  {
    if (velocity_interpolation == VelocityInterpolation::automatic)
      velocity_interpolation = stiff_solid && !band_in_one_change
                                 ? VelocityInterpolation::cubic
                                 : VelocityInterpolation::linear;
    if (automatic_remap_distance)
      remap_distance = velocity_is_prescribed() &&
                           level_set_interpolation ==
                             LevelSetInterpolation::gradient_augmented &&
                           !band_predicted
                         ? (dimension == 2 ? 20 : 14)
                         : 0;
    if (stress_interpolation == StressInterpolation::automatic)
      stress_interpolation =
        velocity_interpolation == VelocityInterpolation::linear
          ? StressInterpolation::linear
          : StressInterpolation::limited_cubic;
  }

  bool
  TransportParameters::feet_linear() const
  {
    Assert(level_set_interpolation != LevelSetInterpolation::automatic,
           ExcMessage("TransportParameters::resolve_level_set() first."));
    // Automatic interpolations are linear with that placement (resolve()).
    return level_set_interpolation == LevelSetInterpolation::linear &&
           (velocity_interpolation == VelocityInterpolation::automatic ||
            velocity_interpolation == VelocityInterpolation::linear) &&
           stress_interpolation != StressInterpolation::limited_cubic;
  }

  bool
  TransportParameters::feet_linear_without_remap() const
  {
    // An automatic remap distance is 0 for a flow (resolve()).
    return feet_linear() && !velocity_is_prescribed() &&
           (automatic_remap_distance || remap_distance == 0);
  }

  bool
  TransportParameters::cubic_stress_interpolation() const
  {
    Assert(stress_interpolation != StressInterpolation::automatic,
           ExcMessage("TransportParameters::resolve() first."));
    return stress_interpolation == StressInterpolation::limited_cubic;
  }
} // namespace vefs
