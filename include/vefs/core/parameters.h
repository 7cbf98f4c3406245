#ifndef vefs_parameters_h
#define vefs_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <vefs/base/cavity.h>
#include <vefs/base/parameter_file.h>
#include <vefs/base/time_control.h>
#include <vefs/core/health_check.h>
#include <vefs/flow/flow_parameters.h>
#include <vefs/io/checkpoint_schedule.h>
#include <vefs/io/postprocessing.h>
#include <vefs/stress/rheology.h>
#include <vefs/transport/initial_liquid.h>
#include <vefs/transport/mesh_adaptation.h>
#include <vefs/transport/transport_parameters.h>

#include <string>
#include <vector>

namespace vefs
{
  /**
   * Every input of a scene: the top-level entries and one struct per module,
   * each declaring its own subsection (doc/parameters.prm lists them all).
   * The defaults describe the default scene, the 2D broken dam of Martin &
   * Moyce (1952) with n^2 = 2.
   *
   * declare() binds the entries to the members: after
   * ParameterHandler::parse_input() they hold the values read, and check()
   * refuses what no module can run.
   */
  struct Parameters
  {
    /** Declares every entry of @p prm, bound to this object's members. */
    void
    declare(dealii::ParameterHandler &prm);

    /**
     * Each module's checks, then those that involve several (the
     * cross-check); throws InputError, and fills warnings.
     */
    void
    check();

    /**
     * The entries set to 'automatic' given their value for the material,
     * the steps and the interpolation at the feet (each entry's
     * documentation says how). Called by check().
     */
    void
    resolve_automatic_entries();

    /**
     * rho |g| L / (3 G), L the cavity's largest extent: the strain its
     * weight would give a column of the solid as tall as the cavity (E = 3
     * G, incompressible); 0 without a stress.
     */
    double
    weight_strain() const;

    /** What a run on @p n_ranks MPI ranks cannot do; throws InputError. */
    void
    check_for_ranks(const unsigned int n_ranks) const;

    /** The entries of several modules that the flow step reads. */
    FlowStepParameters
    flow_step() const
    {
      return {cavity,
              material,
              stress,
              flow,
              solver,
              mesh.max_level,
              time.max_strain_per_step,
              postprocess.energy_budget,
              time.new_force_weight,
              time.time_step};
    }

    /** Entries that have moved to another subsection; their old places are
     * still read, with a warning. */
    static const std::vector<MovedEntry> moved_entries;

    unsigned int dimension        = 2;
    std::string  output_directory = "output";

    TimeParameters          time;
    HealthCheckParameters   health_check;
    CavityParameters        cavity;
    MaterialParameters      material;
    StressParameters        stress;
    InitialLiquidParameters initial_liquid;
    MeshParameters          mesh;
    TransportParameters     transport;
    FlowParameters          flow;
    SolverParameters        solver;
    PostprocessParameters   postprocess;
    CheckpointParameters    checkpoint;
    OutputParameters        output;

    /** Doubtful but accepted input, "entry 'X': what", for the user. */
    std::vector<std::string> warnings;
  };
} // namespace vefs

#endif
