#include <vefs/base/parameter_entries.h>
#include <vefs/stress/rheology.h>

namespace vefs
{
  void
  MaterialParameters::declare(ParameterHandler &prm)
  {
    prm.add_parameter("Gravity",
                      gravity,
                      "Gravitational acceleration vector (m/s^2), one "
                      "component per dimension.",
                      Patterns::List(Patterns::Double(), 2, 3));

    prm.enter_subsection("Material");
    {
      prm.add_parameter("Density",
                        density,
                        "Density rho (kg/m^3), positive.",
                        Patterns::Double());
      prm.add_parameter("Solvent viscosity",
                        solvent_viscosity,
                        "Solvent viscosity eta_s (Pa s), non-negative.",
                        Patterns::Double());
      prm.add_parameter("Polymer viscosity",
                        polymer_viscosity,
                        "Polymer viscosity eta_p (Pa s), non-negative; "
                        "positive in the Oldroyd-B and elastic regimes. In "
                        "the elastic regime the shear modulus is "
                        "G = eta_p / lambda.",
                        Patterns::Double());
      prm.add_parameter("Relaxation time",
                        relaxation_time,
                        "Relaxation time lambda (s). Zero selects the "
                        "Newtonian regime with viscosity eta_s + eta_p; "
                        "positive: the Oldroyd-B liquid (Alpha = 1) or the "
                        "elastic solid (Alpha = 0).",
                        Patterns::Double());
      prm.add_parameter(
        "Alpha",
        alpha,
        "Factor of sigma in the constitutive law alpha sigma + lambda "
        "(upper-convected derivative of sigma) = 2 eta_p eps(u): 1 for "
        "liquids, 0 for the elastic limit, an incompressible neo-Hookean "
        "solid with sigma = G (B - I), G = eta_p / lambda (needs lambda > 0 "
        "and eta_p > 0). A positive solvent viscosity with Alpha = 0 adds a "
        "viscous stress 2 eta_s eps(u): a Kelvin-Voigt solid.",
        Patterns::Integer(0, 1));
      add_selection(
        prm,
        "Stress model",
        stress_model,
        std::vector<std::pair<std::string, StressModel>>{
          {"macroscopic", StressModel::macroscopic},
          {"dumbbells", StressModel::dumbbells}},
        "What carries the polymer stress (Oldroyd-B or elastic regime): "
        "macroscopic, the constitutive law above; dumbbells, 'Dumbbell "
        "fields' Hookean dumbbells as Brownian configuration fields q_i, "
        "sigma = G (<q q^T> - I), whose mean follows the same law "
        "(doc/dumbbells.md). With alpha = 0 the fields are material line "
        "elements and the run equals the macroscopic one.");
      prm.add_parameter("Dumbbell fields",
                        dumbbell_fields,
                        "N_f, the number of configuration fields with 'Stress "
                        "model = dumbbells' (at least the dimension): the "
                        "statistical error of the stress falls like "
                        "N_f^(-1/2), the cost of the transport grows like "
                        "N_f (doc/dumbbells.md).",
                        Patterns::Integer(1, 100000));
      prm.add_parameter("Dumbbell seed",
                        dumbbell_seed,
                        "Seed of the dumbbells' initial vectors and Wiener "
                        "increments: the same seed gives the same run on any "
                        "number of MPI ranks, and a restarted run the same "
                        "increments as the uninterrupted one.",
                        Patterns::Integer(0));
      prm.add_parameter(
        "Dumbbell variance reduction",
        dumbbell_variance_reduction,
        "With dumbbells: the ensemble stress G (<q q^T> - <p p^T>), the p_i "
        "equilibrium fields (no flow) that start from the same vectors and "
        "take the same Wiener increments as the q_i, whose mean <p p^T> is "
        "the identity (the control variate of Oettinger, van den Brule and "
        "Hulsen, 1997): the same mean stress, and where the flow has "
        "deformed the fields little their noise cancels. With alpha = 0 the "
        "p_i stay their initial vectors, <p p^T> = I. false: G (<q q^T> - "
        "I). Measured (doc/dumbbells.md): the Oldroyd-B dam's front 3-5 "
        "times less scattered over seeds, Waters & King's start-up flow, "
        "sheared far from equilibrium, 1-2 % closer; no cost.",
        Patterns::Bool());
    }
    prm.leave_subsection();
  }

  void
  MaterialParameters::check(const unsigned int dimension) const
  {
    require_point(gravity, dimension, "Gravity");
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
    require(!has_dumbbells() || regime() != Regime::newtonian,
            "Material/Stress model",
            "dumbbells carry the polymer stress of the Oldroyd-B or elastic "
            "regime: they need a positive relaxation time");
    require(!has_dumbbells() || dumbbell_fields >= dimension,
            "Material/Dumbbell fields",
            "needs at least as many fields as dimensions, so that <q q^T> "
            "can be the identity");
  }

  void
  StressParameters::resolve()
  {
    if (stress_update == StressUpdate::automatic)
      stress_update = StressUpdate::exponential;
  }

  void
  StressParameters::resolve_nodal_stress(const bool stiff_solid)
  {
    if (nodal_stress == NodalStress::automatic)
      nodal_stress = stiff_solid ? NodalStress::lumped_increment
                                 : NodalStress::vertex_average;
  }

  void
  StressParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Stress");
    {
      add_selection(
        prm,
        "Stress update",
        stress_update,
        std::vector<std::pair<std::string, StressUpdate>>{
          {"automatic", StressUpdate::automatic},
          {"linear", StressUpdate::linear},
          {"exponential", StressUpdate::exponential}},
        "How the conformation tensor c (B for the elastic solid) is carried "
        "by the new velocity gradient L after the diffusion step: linear, "
        "c* + tau (L c* + c* L^T), the seed's first-order formula and the "
        "one the diffusion step sees, which loses positive definiteness "
        "once tau |L| is of order one (an impact); exponential, exp(tau L) "
        "c* exp(tau L)^T, the exact solution for a velocity gradient "
        "constant over the step, positive definite by construction and "
        "equal to the linear one to first order. The relaxation (alpha > 0) "
        "follows in both cases. automatic: exponential. Waters & King's "
        "errors are the same with both (0.0032 at level 2, 0.0030 in the "
        "hard case at CFL 8); at twice and four times the hard case's step "
        "the linear update leaves c with eigenvalues down to -0.04 and "
        "-0.25, the exponential one keeps them above 0.088 "
        "(doc/viscoelastic.md).");
      prm.add_parameter(
        "Stress theta",
        stress_theta,
        "Weight theta in [0.5, 1] of the new velocity u in the stress of "
        "the diffusion step: the stress law sees theta u + (1 - theta) u* "
        "(u* the advected velocity) and the momentum equation the stress "
        "theta sigma^{n+1} + (1 - theta) sigma*. 1: the seed's backward "
        "Euler, which damps elastic oscillations (first order in tau); 0.5: "
        "the midpoint rule, which keeps the energy of a linear elastic "
        "oscillation. No effect on Newtonian liquids. Only with the "
        "first-order 'Time/Scheme' (below 1, 'automatic' chooses it); the "
        "second-order scheme takes the midpoint velocity itself. See "
        "doc/viscoelastic.md.",
        Patterns::Double(0.5, 1));
      add_selection(
        prm,
        "Nodal stress",
        nodal_stress,
        std::vector<std::pair<std::string, NodalStress>>{
          {"automatic", NodalStress::automatic},
          {"vertex average", NodalStress::vertex_average},
          {"lumped increment", NodalStress::lumped_increment}},
        "How the updated stress reaches the nodes, where the next step's "
        "characteristics read it. vertex average: each liquid cell updates "
        "the stress of its vertices with its own velocity gradient there "
        "and the node takes the cell-volume weighted mean (a liquid at rest "
        "keeps its stress exactly). lumped increment: the update's "
        "increment is taken at the quadrature points of the liquid, where "
        "the flow step does work against the stress, and lumped onto the "
        "nodes (weights: the integrals of the shape functions over the "
        "liquid); where that would leave the conformation tensor less than "
        "half as positive as the vertex average, the node takes the "
        "average (the only choice with dumbbells). automatic: lumped "
        "increment for an elastic solid that holds its shape under its "
        "weight (as for 'Transport/Velocity interpolation'), the vertex "
        "average otherwise. With the lumped increment the 2D stiff ball's "
        "first contact loses 10.9 / 4.2 / 2.0 % of its impact energy at "
        "6.25 / 3.12 / 1.56 mm (the average: 10.4 / 5.9 / 4.0 %), the 3D "
        "stiff ball's at 12.5 mm 0.22 J instead of 0.30 J, for 1.03 times "
        "the run time; the soft 3D ball keeps 0.33 of its energy instead of "
        "0.34, the soft 3D beam 0.35 instead of 0.39 (doc/bouncing_ball.md).");
    }
    prm.leave_subsection();
  }
} // namespace vefs
