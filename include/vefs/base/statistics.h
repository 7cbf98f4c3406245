#ifndef vefs_statistics_h
#define vefs_statistics_h

#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <mpi.h>

#include <fstream>
#include <functional>
#include <string>
#include <vector>

namespace vefs
{
  using namespace dealii;

  /** Functionals of the liquid after one time step (doc/method.md, "Outputs").
   */
  template <int dim>
  struct StepStatistics
  {
    unsigned int step   = 0;
    double       time   = 0;
    double       tau    = 0;
    double       cfl    = 0;
    double       volume = 0;
    /** Conservation error: (volume - initial - inflow) / initial. */
    double         volume_change = 0;
    Tensor<1, dim> centroid;
    /**
     * Mean velocity of the liquid, the velocity of its centroid (exact for
     * an incompressible liquid whose volume is kept).
     */
    Tensor<1, dim> centroid_velocity;
    /**
     * The box around the liquid: lowest point, width, the free end of a
     * beam (see widen_to_liquid() in postprocessing.cc).
     */
    Point<dim> liquid_lower;
    Point<dim> liquid_upper;
    double     kinetic_energy   = 0;
    double     potential_energy = 0;
    double     elastic_energy   = 0;
    double     max_velocity     = 0;
    double     floor_extent     = 0;
    double     wall_height      = 0;
    /**
     * The holes in the liquid seen from above (shadow_holes()): positive
     * once a ball's sheet has torn and gathered into a ring.
     */
    double       shadow_holes = 0;
    unsigned int cells        = 0;
    unsigned int liquid_cells = 0;
    /**
     * Cells crossed by the surface right after the advection that are not
     * at the finest level (count_surface_cells()).
     */
    unsigned int coarse_surface_cells = 0;
    /**
     * With 'Band placement = predicted': cells of the mesh the advection
     * ran on (refined ahead of the surface).
     */
    unsigned int advected_cells = 0;
    /**
     * Changes of the mesh in the step: the cycles of the refinement ahead
     * of the surface and the adaptation after the advection. Each rebuilds
     * and transfers the whole mesh, whatever it changes.
     */
    unsigned int mesh_changes      = 0;
    unsigned int dofs              = 0;
    unsigned int linear_iterations = 0;
    double       wall_time         = 0;
    /**
     * Only with an exact final shape: the L1 shape error (at the end time,
     * NaN before) and the surface thickness.
     */
    double shape_error         = 0;
    double interface_thickness = 0;
    /** Only with a stress: see StressMeasure. */
    double       min_conformation_eigenvalue      = 1;
    unsigned int non_positive_conformation_points = 0;
    /**
     * Only with 'Postprocess/Energy budget': the change of the total energy
     * (MechanicalEnergy) in the step's transport (advection, mesh
     * adaptation, redistancing, volume correction), in the flow step with
     * its contact iterations and the stress update, and in the extension
     * beyond the liquid.
     */
    double energy_change_transport = 0;
    double energy_change_flow      = 0;
    double energy_change_extension = 0;
    /**
     * Of energy_change_flow, what the stress update at the nodes adds
     * beyond the same update at the flow step's quadrature points
     * (elastic_energy_of_pointwise_update()): the update's own share; the
     * rest of energy_change_flow is the momentum equation's, with the work
     * of gravity. Only with a macroscopic stress.
     */
    double energy_change_stress_update = 0;
    /**
     * Of energy_change_flow, the work of the contact walls' new reactions
     * on the liquid over the step, tau w R^{n+1} . (u + u*)/2 at the
     * unknowns in contact (w the weight of the new forces; the old
     * reactions act through the carried acceleration): what the walls take
     * from the liquid they stop. Only with contact walls.
     */
    double energy_change_contact = 0;
    /**
     * Only with a stress: c tau / h, how many of the finest cells an
     * elastic shear wave (speed c = sqrt(G / rho)) crosses in the step.
     */
    double elastic_wave_number = 0;
    /** Only with a stress: see StressUpdateReport. */
    double       max_velocity_gradient = 0;
    unsigned int strain_limited_points = 0;
    /**
     * Only with contact walls: the walls' normal force on the liquid over
     * the step, its impulse over tau (see FlowVelocity::measure()), and
     * the contact length (area in 3D) at the end of the step.
     */
    double contact_force   = 0;
    double contact_measure = 0;
    /**
     * Only with contact walls: 1 if the contact set still changed after
     * the step's last allowed solve, which the step then keeps (some of its
     * unknowns in contact pull, or released ones cross the wall), else 0.
     */
    unsigned int unsettled_contact_set = 0;
    /**
     * Only with contact walls: the Stokes solves of the step, one per
     * contact iteration (doc/walls.md, "Contact walls"): what the contact
     * set costs.
     */
    unsigned int stokes_solves = 0;
    /**
     * The walls' reaction in the momentum equation of the step (ContactWalls:
     * the force at the end of the step); kept for the next step's mean.
     */
    double contact_reaction = 0;
    /** Only with a probe point: the velocity there. */
    Tensor<1, dim> probe_velocity;
    /** Only with a probe point and a stress: the stress there. */
    SymmetricTensor<2, dim> probe_stress;
    /** The same with dumbbells: its standard error, per component. */
    SymmetricTensor<2, dim> probe_stress_error;
  };

  /**
   * The `statistics` table, one row a step, written by rank 0. Each column
   * is registered once, with its name and how to read it from a row; the
   * header follows from the registered columns.
   */
  template <int dim>
  class StatisticsFile
  {
  public:
    using Reader = std::function<double(const StepStatistics<dim> &)>;

    /**
     * The file, with the columns every scene has; emptied unless it is for
     * a @p resume (then resume() follows the columns).
     */
    StatisticsFile(const std::string &directory,
                   const MPI_Comm     comm,
                   const bool         resume = false);

    /**
     * Continue the file of the run being resumed: keep its rows up to
     * @p step (those written after the checkpoint are dropped) and append.
     * Throws CheckpointError on all ranks if the file does not have the
     * columns of this scene or ends before @p step.
     */
    void
    resume(const unsigned int step);

    /**
     * Add a column; before the first row only. A column that is not
     * @p finite_every_step may hold NaN where it is not measured (the
     * shape error before the last step).
     */
    void
    add_column(const std::string &name,
               const Reader      &reader,
               const unsigned int precision         = 10,
               const bool         finite_every_step = true);

    /**
     * The first column that must be finite every step and is not in
     * @p row; empty if there is none.
     */
    std::string
    non_finite_column(const StepStatistics<dim> &row) const;

    /**
     * Append @p row (on the root; collective): if the write fails, throws
     * OutputError on every rank.
     */
    void
    write(const StepStatistics<dim> &row);

  private:
    /** Append @p row; what went wrong, or "". */
    std::string
    write_row(const StepStatistics<dim> &row);

    struct Column
    {
      std::string  name;
      Reader       reader;
      unsigned int precision;
      bool         finite_every_step;
    };

    /** The header line of the columns. */
    std::string
    column_header() const;

    const std::string   path;
    const MPI_Comm      comm;
    std::vector<Column> columns;
    bool                header_written = false;
    std::ofstream       file;
  };
} // namespace vefs

#endif
