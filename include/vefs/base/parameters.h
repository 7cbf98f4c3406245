#ifndef vefs_parameters_h
#define vefs_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <vefs/base/errors.h>

#include <array>
#include <stdexcept>
#include <string>
#include <vector>

namespace vefs
{
  /** A point from the comma-separated coordinates of an entry. */
  template <int dim>
  dealii::Point<dim>
  to_point(const std::vector<double> &coordinates)
  {
    dealii::Point<dim> p;
    for (unsigned int d = 0; d < dim; ++d)
      p[d] = coordinates[d];
    return p;
  }

  /** What a cavity wall does to the liquid that touches it. */
  enum class WallType
  {
    no_slip,
    slip,
    open,
    velocity,
    periodic,
    contact
  };

  /** The regime selected by the material parameters (doc/method.md,
   * "Equations"). */
  enum class Regime
  {
    newtonian,
    oldroyd_b,
    elastic_solid
  };

  /** How the velocity is interpolated at the feet of the characteristics. */
  enum class VelocityInterpolation
  {
    linear,
    cubic,
    limited_cubic
  };

  /** How the level set is interpolated at the feet of the characteristics. */
  enum class LevelSetInterpolation
  {
    linear,
    cubic,
    limited_cubic,
    gradient_augmented
  };

  /**
   * How the stress is advanced by the velocity gradient of the step, after
   * the diffusion step (doc/method.md, "One time step", step 9).
   */
  enum class StressUpdate
  {
    linear,
    exponential
  };

  /** Names of the cavity walls, in boundary-id order. */
  const std::array<std::string, 6> wall_names = {
    {"x-", "x+", "y-", "y+", "z-", "z+"}};

  /**
   * Every input of a scene. The defaults describe the default scene, the 2D
   * broken dam of Martin & Moyce (1952) with n^2 = 2.
   */
  struct Parameters
  {
    static void
    declare(dealii::ParameterHandler &prm);

    /** Read the values from @p prm and check them for consistency. */
    void
    parse(dealii::ParameterHandler &prm);

    /** What a run on @p n_ranks MPI ranks cannot do; throws InputError. */
    void
    check_for_ranks(const unsigned int n_ranks) const;

    Regime
    regime() const;

    /** Effective viscosity of the Newtonian regime. */
    double
    newtonian_viscosity() const
    {
      return solvent_viscosity + polymer_viscosity;
    }

    unsigned int dimension;
    std::string  output_directory;

    double end_time;
    double time_step;
    double target_cfl;
    double max_strain_per_step;
    /**
     * Whether the strain bound shortens the next step ('Strain bound =
     * step'); otherwise only the exponential stress update scales the strain
     * down where it is larger ('local').
     */
    bool         strain_bound_shortens_step;
    unsigned int maximum_steps;

    /** Bounds of the health check done after every step. */
    double max_volume_change;
    double max_cfl;
    /** Smallest controlled step, as a fraction of time_step. */
    double min_time_step_fraction;

    std::vector<double>       cavity_lower;
    std::vector<double>       cavity_upper;
    std::vector<unsigned int> coarse_subdivisions;

    std::array<WallType, 6>    wall_type;
    std::array<std::string, 6> wall_velocity;

    double              density;
    double              solvent_viscosity;
    double              polymer_viscosity;
    double              relaxation_time;
    double              alpha;
    std::vector<double> gravity;

    std::string         initial_shape;
    std::vector<double> box_lower;
    std::vector<double> box_upper;
    std::vector<double> ball_center;
    double              ball_radius;
    std::string         level_set_expression;
    std::string         initial_velocity;
    /** Empty: zero initial stress. */
    std::string initial_stress;

    unsigned int min_level;
    unsigned int bulk_level;
    unsigned int max_level;
    double       band_width;
    /**
     * Whether the band is refined ahead of the surface before each advection
     * ('Band placement = predicted') instead of widened by the CFL number.
     */
    bool band_predicted;
    /**
     * Whether that change also coarsens the present band ('Band placement =
     * predicted, one change'), the coarsened cells' fields kept for the
     * advection (CoarsenedDetail, owned by the SurfaceTracker).
     */
    bool band_in_one_change;
    /**
     * The fraction of the surface's cells that may be left coarser than the
     * finest level after the advection before the mesh changes again then
     * ('Band miss tolerance').
     */
    double       band_miss_tolerance;
    unsigned int extension_layers;
    /** Whether the flow's unknowns on the finest cells are their parents'
     * ('Mesh refinement/Flow cells = parents'), see FlowElements. */
    bool flow_on_parents;
    /**
     * Whether the vertices of cut cells outside the liquid take the extended
     * velocity instead of the flow step's ('Outside velocity of cut cells').
     */
    bool extend_outside_velocity;
    /** Whether they take the extended stress ('Outside stress of cut cells').
     */
    bool         extend_outside_stress;
    bool         volume_correction;
    unsigned int redistancing_interval;
    /** Finest cells the surface moves between remaps; 0: every step. */
    double                remap_distance;
    LevelSetInterpolation level_set_interpolation;
    VelocityInterpolation velocity_interpolation;
    /** The stress at the feet by limited cubic ('Stress interpolation'). */
    bool cubic_stress_interpolation;

    double solver_tolerance;
    /** Of the solves while the contact set changes ('Contact tolerance'). */
    double       contact_solver_tolerance;
    unsigned int solver_max_iterations;
    double       pressure_stabilization;
    double       ghost_penalty;
    double       free_surface_stabilization;
    StressUpdate stress_update;
    /** Weight of the new velocity in the stress of the diffusion step. */
    double stress_theta;
    /** Smoother sweeps of both AMG V-cycles (velocity, Schur Laplacian). */
    unsigned int amg_smoother_sweeps;

    std::string prescribed_velocity;
    std::string exact_final_level_set;

    /** Transport only: the velocity is given and the flow is not solved. */
    bool
    velocity_is_prescribed() const
    {
      return !prescribed_velocity.empty();
    }

    /** Empty: no probe. */
    std::vector<double> probe_point;

    /** Coordinate directions whose two walls are periodic. */
    std::vector<unsigned int>
    periodic_directions() const;

    unsigned int checkpoint_interval_steps;
    /** 0: no checkpoints by wall time. */
    double checkpoint_interval_minutes;
    /** 0: no planned stop. */
    unsigned int stop_after_steps;

    unsigned int output_interval;
    double       output_time_interval;
    bool         verbose;

    /** Doubtful but accepted input, "entry 'X': what", for the user. */
    std::vector<std::string> warnings;

  private:
    void
    check();
  };
} // namespace vefs

#endif
