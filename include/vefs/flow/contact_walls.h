#ifndef vefs_contact_walls_h
#define vefs_contact_walls_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/trilinos_block_sparse_matrix.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>

#include <vefs/base/cavity.h>
#include <vefs/flow/flow_elements.h>
#include <vefs/flow/ghost_penalty.h>
#include <vefs/flow/stokes_cell_system.h>

#include <functional>
#include <map>

namespace vefs
{
  /**
   * The seed's Signorini-like walls (doc/walls.md, "Contact walls"): the liquid
   * may leave a contact wall but never cross it, u.n <= 0, with a compressive
   * normal traction where u.n = 0. Solved as an active set on the velocity
   * degrees of freedom normal to the wall: every wet one starts in contact (u.n
   * = 0 imposed); after a solve, one whose reaction pulls the liquid toward the
   * wall is released, and a released one whose velocity crosses the wall is
   * put back, until the set stops changing. The next step's set starts from
   * this one: a wall node released at the end of a step starts released
   * (the mesh changes between steps, so nodes are matched by position).
   */
  template <int dim>
  class ContactWalls
  {
  public:
    using BlockVector = TrilinosWrappers::MPI::BlockVector;

    explicit ContactWalls(const CavityParameters &parameters);

    bool
    empty() const
    {
      return walls.empty();
    }

    /** The boundary ids of the contact walls. */
    const std::vector<types::boundary_id> &
    boundary_ids() const
    {
      return walls;
    }

    /** Whether liquid touches a contact wall on any rank (after reset()). */
    bool
    has_wall_unknowns() const
    {
      return any_wall_unknowns;
    }

    /**
     * After the flow unknowns are distributed: find the degrees of freedom
     * normal to contact walls on liquid cells, but those that
     * @p interpolation constrains (FlowElements); all of them start in
     * contact but those at a node released at the end of the last step.
     * @p touched: the velocity unknowns this rank's cells and faces write
     * into (their reactions too).
     */
    void
    reset(const DoFHandler<dim>           &dof_handler,
          const IndexSet                  &owned,
          const IndexSet                  &relevant,
          const IndexSet                  &touched,
          const unsigned int               liquid_index,
          const AffineConstraints<double> &interpolation);

    /**
     * Set the owned unknowns whose rows hold the contact (u.n = 0) to zero
     * in @p vector (of the flow's blocks, not ghosted).
     */
    void
    set_zero(BlockVector &vector) const;
    /**
     * Keep the rows of the owned contact unknowns of @p matrix and
     * @p rhs, assembled without the contact constraints (unknowns that
     * @p other_constraints constrain excepted), then impose the contact set.
     */
    void
    keep_rows(TrilinosWrappers::BlockSparseMatrix &matrix,
              BlockVector                         &rhs,
              const AffineConstraints<double>     &other_constraints);

    /**
     * u.n = 0 in the rows of the unknowns in contact (row of the identity,
     * scaled by the kept diagonal, zero right-hand side), the kept rows for
     * the others. A row does not need its column cleared: the solution is
     * zero there. Rewrites only the rows whose state changed, so a contact
     * iteration costs no assembly.
     */
    void
    impose(TrilinosWrappers::BlockSparseMatrix &matrix, BlockVector &rhs);

    /**
     * Reactions from the unconstrained residual of @p solution (cell by
     * cell with @p local, face by face with @p ghost_penalty; the residual of
     * an unknown that @p interpolation constrains goes to the unknowns it
     * is interpolated from, the flow space's own), then the active-set
     * update. Returns true if the set changed anywhere (then
     * the constraints must be made again and the set imposed). Also
     * measures the contact force and the contact length (area in 3D).
     */
    bool
    update(const DoFHandler<dim>           &dof_handler,
           const LiquidDomain<dim>         &domain,
           const BlockVector               &solution,
           StokesCellSystem<dim>           &local,
           GhostPenalty<dim>               &ghost_penalty,
           const FlowElements<dim>         &elements,
           const AffineConstraints<double> &interpolation);

    /**
     * Where the next step's contact set starts: the nodes released at the
     * end of this one, gathered from all ranks for a checkpoint.
     * Collective.
     */
    std::vector<Point<dim>>
    saved_state() const;

    /**
     * Start the next step's set from @p released, as saved_state() gave it
     * (on every rank: reset() merges the ranks' lists by position).
     */
    void
    resume(const std::vector<Point<dim>> &released);

    /**
     * The power of the reactions of the last update() on the liquid: the
     * sum over the unknowns in contact in the solution it read of the
     * reaction (the force on the liquid in the unknown's direction) times
     * @p velocity of the unknown (W, W/m in 2D). Collective.
     */
    double
    power(const std::function<double(types::global_dof_index)> &velocity) const;

    /** Normal force of the walls on the liquid in the solution the last
     * update() read (N, N/m in 2D). */
    double force = 0;
    /** Length (2D) or area (3D) of the wall in contact with the liquid. */
    double contact_measure = 0;

  private:
    using Vector = LinearAlgebra::distributed::Vector<double>;

    bool
    is_on_contact_wall(const typename Triangulation<dim>::cell_iterator &cell,
                       const unsigned int face) const;

    /** Boundary ids of the contact walls. */
    std::vector<types::boundary_id> walls;
    /** A degree of freedom normal to a contact wall. */
    struct WallUnknown
    {
      /** Of the outward normal: -1 on a lower wall, +1 on an upper one. */
      int sign;
      /** Where it sits (its vertex). */
      Point<dim> node;
    };
    /** The locally relevant ones, by degree of freedom. */
    std::map<types::global_dof_index, WallUnknown> wall_unknowns;
    /** wall_unknowns is not empty on some rank. */
    bool any_wall_unknowns = false;
    /** A row of the velocity unknown (blocks (0,0) and (0,1)). */
    struct KeptRow
    {
      std::vector<types::global_dof_index> velocity_columns;
      std::vector<double>                  velocity_values;
      std::vector<types::global_dof_index> pressure_columns;
      std::vector<double>                  pressure_values;
      double                               diagonal;
      double                               rhs;
      /** Whether the matrix holds the identity row now. */
      bool imposed;
    };
    /** The owned contact unknowns' rows as assembled, by unknown. */
    std::map<types::global_dof_index, KeptRow> kept_rows;

    /** 1 for a degree of freedom in contact, 0 otherwise; ghosted. */
    Vector in_contact;
    /** The reactions of the last update(), at the owned unknowns. */
    Vector reactions;
    /** The velocity unknowns this rank writes reactions into. */
    IndexSet touched;
    /** Nodes of owned degrees of freedom released by the last update(). */
    std::vector<Point<dim>> released_nodes;
  };
} // namespace vefs

#endif
