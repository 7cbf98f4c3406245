#ifndef vefs_time_control_h
#define vefs_time_control_h

#include <deal.II/base/parameter_handler.h>

#include <functional>
#include <vector>

namespace vefs
{
  /** 'Time/Scheme': the splitting of a flow step. */
  enum class TimeScheme
  {
    automatic,
    first_order,
    second_order
  };

  /** The run's span and the control of its steps: subsection "Time". */
  struct TimeParameters
  {
    void
    declare(dealii::ParameterHandler &prm);

    /** Throws InputError for an entry out of its range. */
    void
    check() const;

    double end_time   = 0.18;
    double time_step  = 0.001;
    double target_cfl = 0;
    /**
     * 'Maximum strain per step'; while @p automatic_max_strain (the entry
     * is 'automatic') it is set by the material: Parameters::check().
     */
    double max_strain_per_step  = 0;
    bool   automatic_max_strain = true;
    /**
     * Whether the strain bound shortens the next step ('Strain bound =
     * step'); otherwise only the exponential stress update scales the strain
     * down where it is larger ('local').
     */
    bool         strain_bound_shortens_step = true;
    unsigned int maximum_steps              = 100000;
    /**
     * 'Scheme = second order': the characteristics trace along the mid-step
     * velocity and the momentum equation takes the mean of the old and new
     * forces (doc/time_step_flow.md, "The second-order scheme"). While
     * @p automatic_scheme it is set by the material: Parameters::check().
     */
    bool second_order = false;
    /** The entry; resolve_scheme() sets second_order from it. */
    TimeScheme scheme = TimeScheme::automatic;
    /**
     * 'New force weight': w of the second-order scheme's momentum equation,
     * 1 for the first-order scheme; set by resolve_scheme() while
     * @p automatic_new_force_weight.
     */
    double new_force_weight           = trapezoidal_new_force_weight;
    bool   automatic_new_force_weight = true;
    /** The trapezoidal rule: second order, damps no mode. */
    static constexpr double trapezoidal_new_force_weight = 0.5;
    /**
     * With contact walls: impacts excite modes of omega tau >> 1, which
     * this weight damps (doc/time_step_flow.md).
     */
    static constexpr double impact_new_force_weight = 0.51;

    /**
     * 'automatic' becomes second order where the scheme has a second-order
     * flow step (@p has_second_order_step: the flow is solved, and its
     * stress law, if any, is one whose relaxation that step integrates: not
     * dumbbells with alpha != 0) unless @p stress_theta is below 1, first
     * order otherwise; the new forces' weight follows the scheme, and in a
     * cavity with contact walls (@p has_contact_walls) it damps impacts.
     * Throws InputError for a weight given to the first-order scheme.
     */
    void
    resolve_scheme(const bool   has_second_order_step,
                   const double stress_theta,
                   const bool   has_contact_walls);
  };

  /** When the visualization is written, and what the screen shows:
   * subsection "Output". */
  struct OutputParameters
  {
    void
    declare(dealii::ParameterHandler &prm);

    unsigned int output_interval      = 10;
    double       output_time_interval = 0;
    /** A progress line per step and the timer summary at the end. */
    bool verbose = true;
  };

  /** The length of a step, and the step the velocity alone allowed. */
  struct TimeStep
  {
    double tau;
    /**
     * The step the CFL and strain bounds allow, before the end time and
     * output times shorten it (the health check watches it for collapse).
     */
    double controlled;
  };

  /**
   * The clock of a run (doc/time_step_surface.md, step 1): the step
   * number, the time, the length and CFL number of the step under way, the
   * end time and the output times the steps land on. It chooses a step from
   * the speeds of the last one; it holds no field.
   */
  class TimeControl
  {
  public:
    /**
     * @p gravity: the body force of the scene (the first step of a body at
     * rest); @p finest_cell_size: the cell size of the CFL number.
     */
    TimeControl(const TimeParameters      &parameters,
                const OutputParameters    &output,
                const std::vector<double> &gravity,
                const double               finest_cell_size);

    /** Continue the run at @p step and @p time (from a checkpoint). */
    void
    resume(const unsigned int step, const double time, const double tau);

    /**
     * The step a flow allows whose last step had the speed @p max_velocity
     * and the largest velocity gradient @p max_velocity_gradient: 'Time
     * step', bounded by the target CFL number and the largest strain per
     * step; from rest under gravity, the step after which gravity alone has
     * moved the liquid by the target CFL number.
     */
    TimeStep
    flow_time_step(const double max_velocity,
                   const double max_velocity_gradient) const;

    /**
     * The step a prescribed velocity allows, with @p speed_at(t) its
     * largest speed in the liquid at time t: the target CFL number holds
     * for the speed at the start, middle and end of the step (a
     * time-dependent velocity may speed up within the step).
     */
    TimeStep
    prescribed_time_step(const std::function<double(double)> &speed_at) const;

    /**
     * @p step shortened to land on the end time and the next output time;
     * a remainder shorter than a quarter step is shared with the step
     * before it.
     */
    TimeStep
    landed(const TimeStep step) const;

    /** The CFL number of a step of length @p tau at @p max_velocity. */
    double
    cfl_of(const double tau, const double max_velocity) const
    {
      return tau * max_velocity / finest_cell_size;
    }

    /** Start the next step, of length @p tau, at the speed @p max_velocity. */
    void
    start_step(const double tau, const double max_velocity);

    /** The step under way is done: the clock moves to its end. */
    void
    end_step();

    /** Whether the end time is reached. */
    bool
    finished() const
    {
      return current_time >= end_time * (1 - 1e-12);
    }

    /** Whether the state now reached is written for visualization. */
    bool
    is_output_step() const;

    unsigned int
    step() const
    {
      return current_step;
    }

    /** The start of the step under way, its end once end_step() is done. */
    double
    time() const
    {
      return current_time;
    }

    /** The length of the step under way (or the last one). */
    double
    tau() const
    {
      return current_tau;
    }

    /** tau max|u| / h of the step under way, with the speed it started at. */
    double
    cfl() const
    {
      return current_cfl;
    }

    /**
     * The CFL number the next step is expected to have: the target, or
     * that of the step under way if larger (the surface moves about as far
     * in the next step as in this one).
     */
    double
    expected_cfl() const
    {
      return std::max(target_cfl, current_cfl);
    }

    /** The end time, for the estimate of the time left. */
    double
    end() const
    {
      return end_time;
    }

  private:
    /** The first multiple of 'Output/Time interval' after @p time. */
    double
    next_output_time(const double time) const;

    const double       end_time;
    const double       time_step;
    const double       target_cfl;
    const double       max_strain_per_step;
    const bool         strain_bound_shortens_step;
    const double       output_time_interval;
    const unsigned int output_interval;
    const double       gravity;
    const double       finest_cell_size;

    unsigned int current_step = 0;
    double       current_time = 0;
    double       current_tau  = 0;
    double       current_cfl  = 0;

    /** The shortest step before an end or output time, as a fraction of the
     * step before it. */
    static constexpr double min_step_fraction = 0.25;
  };
} // namespace vefs

#endif
