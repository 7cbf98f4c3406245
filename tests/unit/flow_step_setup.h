#ifndef vefs_unit_flow_step_setup_h
#define vefs_unit_flow_step_setup_h

// The parameter sections a flow step reads, at their defaults, for the
// unit tests of the flow step's pieces (StokesCellSystem, GhostPenalty):
// a test changes the entries it needs, resolves the stress update, and
// takes step().

#include <vefs/flow/flow_parameters.h>

namespace unit_test
{
  struct FlowStepSetup
  {
    vefs::CavityParameters   cavity;
    vefs::MaterialParameters material;
    vefs::StressParameters   stress;
    vefs::FlowParameters     flow;
    vefs::SolverParameters   solver;

    /**
     * The first-order step of length @p tau with finest cells of level
     * @p max_level, no strain bound, no energy budget (new force weight 1); it
     * refers to the members above.
     */
    vefs::FlowStepParameters
    step(const unsigned int max_level, const double tau) const
    {
      return {cavity,
              material,
              stress,
              flow,
              solver,
              max_level,
              0.,
              false,
              1.,
              tau};
    }
  };
} // namespace unit_test

#endif
