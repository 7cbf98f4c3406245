#ifndef vefs_stokes_step_h
#define vefs_stokes_step_h

#include <deal.II/base/function.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/hp/fe_collection.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_block_sparse_matrix.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>
#include <deal.II/lac/trilinos_precondition.h>

#include <vefs/base/errors.h>
#include <vefs/compat/constraint_distribution.h>
#include <vefs/fields/transported_fields.h>
#include <vefs/flow/contact_walls.h>
#include <vefs/flow/flow_elements.h>
#include <vefs/flow/flow_numbering.h>
#include <vefs/flow/flow_parameters.h>
#include <vefs/flow/ghost_penalty.h>
#include <vefs/stress/rheology.h>
#include <vefs/transport/liquid_domain.h>

#include <memory>

namespace vefs
{
  /**
   * The diffusion (correction) step of the splitting, doc/time_step_flow.md,
   * step 7: the Stokes-like problem
   *   rho (u - u*)/tau - div(2 mu eps(u) + k sigma*) + grad p = rho g,
   *   div u = 0
   * on the liquid domain psi < 0, cut out of the cells the free surface
   * crosses (LiquidDomain), so that the surface itself carries the natural
   * zero-traction condition. Elements: Q1-Q1 with consistent pressure
   * stabilisation (PSPG) on every cell whose flow element (FlowElements)
   * holds liquid, FE_Nothing
   * elsewhere, and a ghost penalty on the faces of cut cells.
   */
  template <int dim>
  class StokesStep
  {
  public:
    using BlockVector = TrilinosWrappers::MPI::BlockVector;

    /**
     * @p rheology: the stress law of the run, the object the stress update
     * uses too: the momentum equation's stress coefficients must be those
     * of the update, which the time scheme sets for both.
     */
    StokesStep(const FlowStepParameters                        &parameters,
               const Rheology<dim>                             &rheology,
               const parallel::distributed::Triangulation<dim> &triangulation);

    /** Flow unknowns on the cells of @p domain that hold liquid. */
    void
    setup(const LiquidDomain<dim> &domain, const double time);

    /** Assemble with u* = the advected velocity of @p fields. */
    void
    assemble(const TransportedFields<dim> &fields, const double tau);

    /**
     * Build the AMG hierarchies of the step's solves from the assembled
     * matrices (solve() builds them if this was not called: it is separate
     * so that the timer shows its cost apart from the Krylov iterations).
     */
    void
    build_preconditioner();

    /**
     * Solve to the relative residual @p tolerance, from the last solution
     * if this is a contact iteration. Returns the number of Krylov
     * iterations; throws SolverError.
     */
    unsigned int
    solve(const double tolerance);

    /**
     * With contact walls: update the contact set from the last solution
     * (doc/walls.md, "Contact walls"). Returns true if it changed; then the
     * constraints and the rows of the changed unknowns are remade, and the step
     * must be solved again (not assembled).
     */
    bool
    update_contact(const TransportedFields<dim> &fields, const double tau);

    bool
    has_contact_walls() const
    {
      return !contact.empty();
    }

    /** Whether liquid touches a contact wall this step (after setup()). */
    bool
    touches_contact_walls() const
    {
      return contact.has_wall_unknowns();
    }

    /** Normal force of the contact walls on the liquid (N; N/m in 2D). */
    double
    contact_force() const
    {
      return contact.force;
    }

    /**
     * The power of the contact walls' reactions of the last contact update
     * on the liquid, at the mid-step velocity (u + u*)/2 of the unknowns in
     * contact (u* the advected velocity that @p fields hold during the
     * solve; u = 0 there): W, W/m in 2D. Collective.
     */
    double
    contact_power(const TransportedFields<dim> &fields) const;

    /** ContactWalls::saved_state(), for a checkpoint. Collective. */
    std::vector<Point<dim>>
    contact_state() const
    {
      return contact.saved_state();
    }

    /** Start the next step's contact set from a checkpoint's state. */
    void
    resume_contact(const std::vector<Point<dim>> &released)
    {
      contact.resume(released);
    }

    /** Length (2D) or area (3D) of contact-wall in contact with liquid. */
    double
    contact_measure() const
    {
      return contact.contact_measure;
    }

    /**
     * Write the new velocity into the nodes of liquid cells of @p fields and
     * flag them in @p known.
     */
    void
    copy_velocity_to(TransportedFields<dim>                      &fields,
                     typename TransportedFields<dim>::VectorType &known) const;

    /**
     * Net rate (m^3/s, m^2/s in 2D) at which liquid leaves through the
     * cavity walls: the integral of u.n over the liquid's faces on them, of
     * a cut cell over the wet part of the face (non-zero on 'velocity' and
     * 'open' walls only).
     */
    double
    outflow_rate() const;

    /** The flow's unknowns: with coarser 'Flow cells' those of the
     * elements' Q1 space, not the interpolated ones of the finer cells. */
    types::global_dof_index
    n_dofs() const
    {
      return numbering.n_flow_dofs();
    }

    const DoFHandler<dim> &
    get_dof_handler() const
    {
      return dof_handler;
    }

    const BlockVector &
    get_solution() const
    {
      return solution;
    }

  private:
    /**
     * The integral of u.n over the part of boundary face @p f of @p cell
     * that the rule @p wet covers (points on the reference cell's face,
     * weights of the reference face).
     */
    double
    face_flux(const typename DoFHandler<dim>::active_cell_iterator &cell,
              const unsigned int                                    f,
              const Quadrature<dim>                                &wet) const;

    static constexpr unsigned int liquid_index = 0;
    static constexpr unsigned int empty_index  = 1;

    void
    make_wall_constraints(AffineConstraints<double> &constraints) const;
    /**
     * The same for the unknowns this rank writes into at the vertices of
     * ghost cells' elements that it does not otherwise see
     * (FlowElements::far_element_dofs()).
     */
    void
    make_far_element_wall_constraints(
      AffineConstraints<double> &constraints) const;

    /**
     * The periodicity constraints of deal.II 9.4 need the same element on
     * both sides of a periodic face: stop with a message where the liquid
     * meets empty space across periodic walls.
     */
    void
    check_periodic_liquid() const;

    /** The constraints of the step but the contact set. */
    void
    make_constraints();

    /** Sparsity patterns, matrices and vectors for the current dofs. */
    void
    make_matrices();

    const FlowStepParameters parameters;
    const MPI_Comm           comm;
    hp::FECollection<dim>    fe_collection;
    DoFHandler<dim>          dof_handler;
    /** Of the flow system's blocks (FlowNumbering::flow_blocks()). */
    std::vector<IndexSet> owned_partitioning;
    std::vector<IndexSet> relevant_partitioning;
    IndexSet              relevant_dofs;
    /**
     * The unknowns whose constraints and matrix rows this rank touches: the
     * locally relevant ones and, with coarser 'Flow cells', the far
     * vertices of ghost cells' elements.
     */
    IndexSet              touched_dofs;
    std::vector<IndexSet> touched_partitioning;
    /**
     * Hanging-node, periodic, wall and (with coarser 'Flow cells') the
     * interpolation constraints; not the contact set, which ContactWalls
     * imposes on the matrix rows, so that a contact iteration needs neither
     * an assembly nor new constraints.
     */
    AffineConstraints<double> constraints;
    /** constraints.distribute() on the solution, by local indices. */
    ConstraintDistribution                        constraint_distribution;
    std::array<std::unique_ptr<Function<dim>>, 6> wall_velocity;

    TrilinosWrappers::BlockSparseMatrix system_matrix;
    /**
     * The approximation L_w of the Schur complement, for the pressure
     * Laplacian's AMG: on the pressure unknowns only, numbered within the
     * pressure block, so that no velocity blocks are built each step.
     */
    TrilinosWrappers::SparseMatrix schur_matrix;
    /** The constraints of the pressure unknowns, numbered as schur_matrix. */
    AffineConstraints<double> pressure_constraints;
    BlockVector               system_rhs;
    BlockVector               lumped_pressure_mass;
    /** The last solve's, in the flow space's own unknowns (owned). */
    BlockVector flow_solution;
    /** All parts (FlowNumbering::all_parts()), owned: each solve fills it
     * and distributes the constraints into it. */
    BlockVector owned_solution;
    /** The owned unknowns of the flow space that the constraints constrain:
     * zero in the Krylov space (set up with the constraints). */
    std::vector<types::global_dof_index> owned_constrained_flow_dofs;
    /** All parts (FlowNumbering), ghosted: what cells read. */
    BlockVector          solution;
    const Rheology<dim> &rheology;
    ContactWalls<dim>    contact;
    FlowElements<dim>    elements;
    /** The unknowns of cells interpolated from their coarser element's
     * (FlowElements), a part of every other set of constraints. */
    AffineConstraints<double> interpolation;
    /** The flow space's own unknowns first, the interpolated ones after. */
    FlowNumbering numbering;
    /** Time of the step being solved (for the wall velocities). */
    double time = 0;
    /** The liquid of the step being solved, from setup(). */
    const LiquidDomain<dim> *domain = nullptr;

    /**
     * What a step keeps through its contact iterations, which change only
     * the rows of the contact unknowns: the cell and face terms (same
     * fields, liquid domain and tau; the reactions need those at the walls),
     * and the AMG hierarchies of its first solve (only the rows
     * of the velocity block that the contact set constrains change, so they
     * still precondition the later solves, which FGMRES allows; the
     * pressure Laplacian does not change at all).
     */
    struct StepSystems
    {
      StokesCellSystem<dim>                              cells;
      GhostPenalty<dim>                                  faces;
      double                                             tau;
      std::unique_ptr<TrilinosWrappers::PreconditionAMG> velocity_amg;
      std::unique_ptr<TrilinosWrappers::PreconditionAMG> laplace_amg;
      /** Solves so far: the later ones are contact iterations. */
      unsigned int n_solves = 0;
    };

    /** Those of the step, made by its first assembly after setup(). */
    StepSystems &
    systems_of_step(const TransportedFields<dim> &fields, const double tau);

    std::unique_ptr<StepSystems> step_systems;

    /** Build the AMG hierarchies of @p systems from the current matrices. */
    void
    make_amg_hierarchies(StepSystems &systems) const;
  };
} // namespace vefs

#endif
