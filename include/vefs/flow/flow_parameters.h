#ifndef vefs_flow_parameters_h
#define vefs_flow_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <vefs/base/cavity.h>
#include <vefs/stress/rheology.h>

namespace vefs
{
  /** The velocity at the vertices of cut cells outside the liquid. */
  enum class OutsideVelocity
  {
    /** Resolved by the material's regime: FlowParameters::resolve(). */
    automatic,
    solution,
    /** Extension at the vertices on slip and contact walls. */
    extension_at_walls,
    extension
  };

  /** The stress at the vertices of cut cells outside the liquid. */
  enum class OutsideStress
  {
    /** Resolved by the material's regime: FlowParameters::resolve(). */
    automatic,
    updated,
    extension
  };

  /**
   * Where the flow is solved and what the characteristics see beyond it:
   * subsection "Flow".
   */
  struct FlowParameters
  {
    void
    declare(dealii::ParameterHandler &prm);

    /**
     * 'automatic' outside stress becomes extension for an elastic solid
     * (the updated one feeds energy into a body at rest:
     * doc/oscillating_beam.md) and updated, the seed's, for a liquid;
     * 'automatic' outside velocity: extension at walls for an elastic solid
     * that holds its shape under its weight (the solution on the wall beside
     * its contact line costs a bouncing body energy, and the extension at
     * every outside vertex makes a body vibrating freely gain energy on
     * coarse cells: doc/bouncing_ball.md), the solution otherwise.
     */
    void
    resolve(const Regime regime,
            const bool   dumbbells,
            const bool   stiff_solid_under_gravity);

    /**
     * Which vertices of cut cells outside the liquid take the extended
     * velocity instead of the flow step's ('Outside velocity of cut cells').
     */
    OutsideVelocity
    resolved_outside_velocity() const
    {
      Assert(outside_velocity != OutsideVelocity::automatic,
             dealii::ExcMessage("FlowParameters::resolve() first."));
      return outside_velocity;
    }

    /**
     * Whether the vertices of cut cells outside the liquid take the extended
     * stress ('Outside stress of cut cells').
     */
    bool
    extends_outside_stress() const
    {
      Assert(outside_stress != OutsideStress::automatic,
             dealii::ExcMessage("FlowParameters::resolve() first."));
      return outside_stress == OutsideStress::extension;
    }

    /** How many levels the flow's elements are coarser than the finest
     * cells ('Flow cells': finest 0, parents 1), see FlowElements. */
    unsigned int flow_level_offset = 0;
    /**
     * Whether the elements that touch a contact wall keep the finest cells
     * ('Finest cells at contact walls'), see FlowElements.
     */
    bool            finest_at_contact_walls = false;
    unsigned int    extension_layers        = 4;
    OutsideVelocity outside_velocity        = OutsideVelocity::automatic;
    OutsideStress   outside_stress          = OutsideStress::automatic;
  };

  /** The linear solves and the stabilizations: subsection "Solver". */
  struct SolverParameters
  {
    void
    declare(dealii::ParameterHandler &prm);

    /** Throws InputError for a tolerance no solve can reach. */
    void
    check() const;

    /**
     * 'automatic' pressure stabilization: 0.01 for an elastic solid that
     * holds its shape under its weight (0.25 lets it creep:
     * doc/oscillating_beam.md, "A stiff beam at rest"; 0.05 costs a
     * bouncing body more energy: doc/bouncing_ball.md), 0.25 otherwise.
     */
    void
    resolve(const bool stiff_solid_under_gravity);

    double solver_tolerance = 1e-8;
    /** Of the solves while the contact set changes ('Contact tolerance'). */
    double       contact_solver_tolerance = 1e-4;
    unsigned int solver_max_iterations    = 1000;
    /** Smoother sweeps of both AMG V-cycles (velocity, Schur Laplacian). */
    unsigned int amg_smoother_sweeps              = 4;
    double       pressure_stabilization           = 0.25;
    bool         automatic_pressure_stabilization = true;
    double       free_surface_stabilization       = 0;
    double       ghost_penalty                    = 0.1;
    /**
     * Liquid fraction below which a cut cell's vertices get the lumped mass
     * of the missing fraction of the whole cell, moving with u*; 0: off.
     */
    double small_cut_cell_mass = 0.01;
  };

  /**
   * What the flow step reads of the scene: the entries of the modules it
   * works with, and the two numbers it needs from the mesh and the time
   * control.
   */
  struct FlowStepParameters
  {
    const CavityParameters   &cavity;
    const MaterialParameters &material;
    const StressParameters   &stress;
    const FlowParameters     &flow;
    const SolverParameters   &solver;
    /** 'Mesh refinement/Maximum level': the level of the finest cells. */
    unsigned int max_level;
    /** 'Time/Maximum strain per step' (0: none). */
    double max_strain_per_step;
    /** 'Postprocess/Energy budget': the energy changes of each stage. */
    bool energy_budget;
    /**
     * The weight w of the new forces in the momentum equation, (rho / (w
     * tau)) (u - u*) = F^{n+1} + ((1 - w) / w) rho a*: 1 for the first-order
     * scheme, 'Time/New force weight' for the second-order one (0.51 by
     * default, not the trapezoidal 1/2, which leaves the alternating part of
     * a constraint force undamped: the 2D stiff ball's contact force
     * alternated by 47 % of itself from step to step, 3 % with 0.51;
     * doc/time_step_flow.md).
     */
    double new_force_weight;

    /** The step w tau of the mass term (and of the stabilisations). */
    double
    mass_step(const double tau) const
    {
      return new_force_weight * tau;
    }

    /**
     * (1 - w) tau: rho / (w tau) (u* + (1 - w) tau a*) puts the old forces
     * beside the mass term; 0 for the first-order scheme.
     */
    double
    old_force_step(const double tau) const
    {
      return (1 - new_force_weight) * tau;
    }
    /** 'Time/Time step': the scale of the step that finds the acceleration
     * of a new run with the second-order scheme. */
    double time_step;
  };
} // namespace vefs

#endif
