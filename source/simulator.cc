#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>

#include <vefs/characteristics.h>
#include <vefs/field_extension.h>
#include <vefs/free_surface.h>
#include <vefs/health_check.h>
#include <vefs/initial_liquid.h>
#include <vefs/redistancing.h>
#include <vefs/simulator.h>
#include <vefs/stop_signal.h>
#include <vefs/stress.h>

#include <filesystem>
#include <iomanip>
#include <sstream>

namespace vefs
{
  namespace
  {
    std::string
    printed(const ParameterHandler &prm)
    {
      std::ostringstream text;
      prm.print_parameters(text, ParameterHandler::PRM);
      return text.str();
    }
  } // namespace

  template <int dim>
  Simulator<dim>::Simulator(const Parameters       &parameters,
                            const ParameterHandler &prm,
                            const std::string      &checkpoint)
    : parameters(parameters)
    , parameters_text(printed(prm))
    , checkpoint(checkpoint)
    , rheology(parameters)
    , comm(MPI_COMM_WORLD)
    , output(parameters.output_directory, comm, !checkpoint.empty())
    , pcout(std::cout,
            parameters.verbose && Utilities::MPI::this_mpi_process(comm) == 0)
    , timer(comm,
            pcout,
            parameters.verbose ? TimerOutput::summary : TimerOutput::never,
            TimerOutput::wall_times)
    // Each mesh change rebuilds the local mesh from the coarse cells instead
    // of refining and coarsening it until it matches p4est's: fewer passes
    // on several ranks, and the cells lie in memory in p4est's order (the
    // space-filling curve), which every loop over them gains from
    // (doc/bouncing_ball_3d_study.md, "The local mesh rebuilt from the
    // coarse cells").
    , triangulation(comm,
                    Triangulation<dim>::limit_level_difference_at_vertices,
                    parallel::distributed::Triangulation<
                      dim>::mesh_reconstruction_after_repartitioning)
    , cavity(std::make_pair(to_point<dim>(parameters.cavity_lower),
                            to_point<dim>(parameters.cavity_upper)))
    , levels(parameters)
    , fields(triangulation,
             rheology.has_stress(),
             parameters.periodic_directions())
    , level_set_history(parameters.remap_distance)
    , flow(parameters, triangulation)
    , statistics_file(output.path(), comm, !checkpoint.empty())
    , visualization(parameters.output_directory)
  {
    if (parameters.velocity_is_prescribed())
      prescribed_velocity = make_prescribed_velocity<dim>(parameters);
    if (!parameters.exact_final_level_set.empty())
      exact_final_level_set = make_exact_final_level_set<dim>(parameters);
    add_scene_columns();
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        std::ofstream file(parameters.output_directory + "/parameters.prm");
        file << parameters_text;
      }
  }

  template <int dim>
  void
  Simulator<dim>::add_scene_columns()
  {
    if (exact_final_level_set)
      {
        // Measured at the end time only: NaN before.
        statistics_file.add_column(
          "shape_error",
          [](const auto &s) { return s.shape_error; },
          10,
          false);
        statistics_file.add_column("interface_thickness", [](const auto &s) {
          return s.interface_thickness;
        });
      }
    if (rheology.has_stress())
      {
        statistics_file.add_column("min_conformation_eigenvalue",
                                   [](const auto &s) {
                                     return s.min_conformation_eigenvalue;
                                   });
        statistics_file.add_column("non_positive_conformation_points",
                                   [](const auto &s) {
                                     return s.non_positive_conformation_points;
                                   });
        statistics_file.add_column("max_velocity_gradient", [](const auto &s) {
          return s.max_velocity_gradient;
        });
        if (parameters.stress_update == StressUpdate::exponential &&
            parameters.max_strain_per_step > 0)
          statistics_file.add_column("strain_limited_points",
                                     [](const auto &s) {
                                       return s.strain_limited_points;
                                     });
      }
    if (flow.has_contact_walls())
      {
        statistics_file.add_column("contact_force", [](const auto &s) {
          return s.contact_force;
        });
        statistics_file.add_column(dim == 2 ? "contact_length" : "contact_area",
                                   [](const auto &s) {
                                     return s.contact_measure;
                                   });
      }
    if (parameters.band_predicted)
      statistics_file.add_column("advected_cells", [](const auto &s) {
        return s.advected_cells;
      });
    if (!parameters.probe_point.empty())
      for (unsigned int d = 0; d < dim; ++d)
        statistics_file.add_column(std::string("probe_u_") + "xyz"[d],
                                   [d](const auto &s) {
                                     return s.probe_velocity[d];
                                   });
  }

  template <int dim>
  void
  Simulator<dim>::make_cavity()
  {
    std::vector<unsigned int> subdivisions(
      parameters.coarse_subdivisions.begin(),
      parameters.coarse_subdivisions.end());
    // colorize: boundary ids 0..2dim-1 for the walls x-, x+, y-, y+, z-, z+.
    GridGenerator::subdivided_hyper_rectangle(
      triangulation,
      subdivisions,
      cavity.get_boundary_points().first,
      cavity.get_boundary_points().second,
      true);
    for (const unsigned int d : parameters.periodic_directions())
      {
        std::vector<GridTools::PeriodicFacePair<
          typename parallel::distributed::Triangulation<dim>::cell_iterator>>
          pairs;
        GridTools::collect_periodic_faces(triangulation,
                                          2 * d,
                                          2 * d + 1,
                                          d,
                                          pairs);
        triangulation.add_periodicity(pairs);
      }
    // p4est balances the work: a cell with liquid costs the flow solve, an
    // empty one only the transport. A family to be coarsened is weighed
    // through its parent, whose own mark dates from its refinement: it has
    // liquid if a child has.
    triangulation.signals.weight.connect(
      [](const typename Triangulation<dim>::cell_iterator &cell,
         const typename Triangulation<dim>::CellStatus status) -> unsigned int {
        bool liquid = cell->material_id() == liquid_material_id;
        if (status == Triangulation<dim>::CELL_COARSEN)
          {
            AssertThrow(cell->has_children(), ExcInternalError());
            liquid = false;
            for (const auto &child : cell->child_iterators())
              liquid |= child->material_id() == liquid_material_id;
          }
        return liquid ? 4 : 1;
      });
    locator = std::make_unique<BoxMeshLocator<dim>>(triangulation,
                                                    cavity,
                                                    subdivisions,
                                                    parameters.wall_type);
  }

  template <int dim>
  void
  Simulator<dim>::set_initial_state()
  {
    const auto level_set = make_initial_level_set<dim>(parameters);
    const auto velocity  = make_initial_velocity<dim>(parameters);
    const auto stress    = make_initial_stress<dim>(parameters);
    triangulation.refine_global(parameters.min_level);
    fields.setup_dofs();
    // Refine toward the initial surface, evaluating it exactly on each mesh.
    // A level set whose slope varies may make a cell and its children want
    // different levels: the cycles are bounded.
    for (unsigned int cycle = 0;; ++cycle)
      {
        fields.interpolate(*level_set, *velocity, stress.get());
        if (cycle == parameters.max_level ||
            !adapt_mesh(triangulation,
                        fields,
                        levels,
                        1,
                        LevelSetInterpolation::linear))
          break;
      }
    if (prescribed_velocity)
      {
        prescribed_velocity->set_time(0);
        fields.set_velocity(*prescribed_velocity);
      }
    initial_volume  = sharp_liquid_volume(fields, 0).volume;
    expected_volume = initial_volume;
    if (!std::isfinite(initial_volume) || !fields_are_finite(fields))
      throw InputError("entry 'Initial liquid/Shape': the initial level set, "
                       "velocity or stress is not finite somewhere in the "
                       "cavity (check 'Initial liquid/Level set expression', "
                       "'Initial liquid/Velocity', 'Initial liquid/Stress')");
    if (!(initial_volume > 0))
      throw InputError("entry 'Initial liquid/Shape': the initial liquid "
                       "does not intersect the cavity");
  }

  template <int dim>
  StepStatistics<dim>
  Simulator<dim>::resume()
  {
    const RunState<dim> state =
      read_checkpoint(checkpoint, triangulation, fields, level_set_history);
    initial_volume   = state.initial_volume;
    expected_volume  = state.expected_volume;
    last_output_step = state.last_output_step;
    wall_time_offset = state.statistics.wall_time;
    visualization.resume(state.visualization_series);
    statistics_file.resume(state.statistics.step);
    return state.statistics;
  }

  template <int dim>
  std::optional<RunEnd>
  Simulator<dim>::checkpoint_if_due(const StepStatistics<dim> &statistics,
                                    const unsigned int         steps_done)
  {
    if (is_last_step(statistics))
      return {};
    // Every rank takes the same decision.
    const int  signal       = Utilities::MPI::max(received_stop_signal(), comm);
    const bool planned_stop = parameters.stop_after_steps > 0 &&
                              steps_done >= parameters.stop_after_steps;
    const bool by_steps =
      parameters.checkpoint_interval_steps > 0 &&
      statistics.step % parameters.checkpoint_interval_steps == 0;
    const bool by_time =
      Utilities::MPI::logical_or(parameters.checkpoint_interval_minutes > 0 &&
                                   since_checkpoint.wall_time() >=
                                     60 *
                                       parameters.checkpoint_interval_minutes,
                                 comm);
    if (signal == 0 && !planned_stop && !by_steps && !by_time)
      return {};

    std::string problem;
    {
      TimerOutput::Scope  scope(timer, "checkpoint");
      const RunState<dim> state{statistics,
                                initial_volume,
                                expected_volume,
                                last_output_step,
                                visualization.get_series()};
      Timer               writing;
      problem = write_checkpoint(parameters.output_directory,
                                 parameters_text,
                                 fields,
                                 level_set_history,
                                 state);
      if (problem.empty())
        pcout << "checkpoint of step " << statistics.step << " written in "
              << std::setprecision(3) << writing.wall_time() << " s"
              << std::endl;
    }
    since_checkpoint.restart();
    const std::string directory =
      parameters.output_directory + "/" + CheckpointNames::current;
    std::ostringstream where;
    where << "step " << statistics.step << " (t = " << statistics.time << ")";
    if (!problem.empty())
      {
        const std::string failure =
          "the checkpoint of " + where.str() + " was not written: " + problem;
        if (signal != 0 || planned_stop)
          throw SolverError(failure + "; the statistics end with step " +
                            std::to_string(statistics.step));
        if (Utilities::MPI::this_mpi_process(comm) == 0)
          std::cerr << "vefs: warning: " << failure << std::endl;
        return {};
      }
    const std::string resume_hint = "; the checkpoint is in " + directory +
                                    "/, continue with: vefs --resume " +
                                    parameters.output_directory;
    if (signal != 0)
      return RunEnd{128 + signal,
                    std::string("stopped by ") + signal_name(signal) +
                      " after " + where.str() + resume_hint};
    if (planned_stop)
      return RunEnd{0,
                    "stopped after " + where.str() + ", " +
                      std::to_string(steps_done) +
                      " steps as set by 'Checkpoint/Stop after steps'" +
                      resume_hint};
    return {};
  }

  template <int dim>
  double
  Simulator<dim>::choose_time_step(const StepStatistics<dim> &last) const
  {
    const double max_velocity = last.max_velocity;
    double       tau          = parameters.time_step;
    if (parameters.max_strain_per_step > 0 &&
        parameters.strain_bound_shortens_step && last.max_velocity_gradient > 0)
      tau =
        std::min(tau,
                 parameters.max_strain_per_step / last.max_velocity_gradient);
    if (parameters.target_cfl > 0)
      {
        const double h = levels.finest_cell_size;
        if (max_velocity > 0)
          tau = std::min(tau, parameters.target_cfl * h / max_velocity);
        else
          {
            // From rest, gravity alone sets the speed: |g| tau after a step,
            // which has crossed CFL cells when tau = sqrt(CFL h / |g|).
            double g = 0;
            for (const double component : parameters.gravity)
              g += component * component;
            if (g > 0)
              tau =
                std::min(tau,
                         std::sqrt(parameters.target_cfl * h / std::sqrt(g)));
          }
      }
    return tau;
  }

  template <int dim>
  typename Simulator<dim>::StepLength
  Simulator<dim>::choose_step_length(
    const StepStatistics<dim> &statistics) const
  {
    // A prescribed velocity cannot blow up: only the flow's step is watched
    // for collapse.
    StepLength step;
    if (prescribed_velocity)
      {
        step.controlled = parameters.time_step;
        step.tau        = choose_prescribed_time_step(statistics.time);
      }
    else
      {
        step.controlled = choose_time_step(statistics);
        step.tau        = step.controlled;
      }
    double target = parameters.end_time;
    if (parameters.output_time_interval > 0)
      target = std::min(target, next_output_time(statistics.time));
    const double remaining = target - statistics.time;
    // Within round-off of the step (fixed steps that divide the interval)
    // the step lands on the target.
    if (remaining <= step.tau * (1 + 1e-9))
      step.tau = remaining;
    else if (remaining < (1 + min_step_fraction) * step.tau)
      // Two halves instead of a full step and a sliver: a sliver costs a
      // whole solve, and the contact force (a velocity change over tau) of
      // a step of 1e-4 tau is noise (3D ball: 92 N at the end, 40 N before).
      step.tau = remaining / 2;
    return step;
  }

  template <int dim>
  double
  Simulator<dim>::next_output_time(const double time) const
  {
    const double interval = parameters.output_time_interval;
    // A time that landed on a multiple up to round-off counts as on it.
    return (std::floor(time / interval + 1e-9) + 1) * interval;
  }

  template <int dim>
  bool
  Simulator<dim>::is_output_step(const StepStatistics<dim> &statistics) const
  {
    if (is_last_step(statistics) &&
        (parameters.output_interval > 0 || parameters.output_time_interval > 0))
      return true;
    if (parameters.output_time_interval > 0)
      {
        const double in_intervals =
          statistics.time / parameters.output_time_interval;
        return std::abs(in_intervals - std::round(in_intervals)) < 1e-9;
      }
    return parameters.output_interval > 0 &&
           statistics.step % parameters.output_interval == 0;
  }

  template <int dim>
  double
  Simulator<dim>::prescribed_speed(const double time) const
  {
    prescribed_velocity->set_time(time);
    double speed = 0;
    for (const auto &node : fields.nodes())
      if (fields.fields(
            node.dofs[TransportedFields<dim>::level_set_component]) <= 0)
        {
          Tensor<1, dim> u;
          for (unsigned int d = 0; d < dim; ++d)
            u[d] = prescribed_velocity->value(node.point, d);
          speed = std::max(speed, u.norm());
        }
    return Utilities::MPI::max(speed, comm);
  }

  template <int dim>
  double
  Simulator<dim>::choose_prescribed_time_step(const double time) const
  {
    // A time-dependent velocity may speed up within the step (after the
    // reversal of the deformation test, say): bound the speed at the start,
    // middle and end of the step, and shrink the step until it fits.
    double tau = std::min(parameters.time_step, parameters.end_time - time);
    if (parameters.target_cfl == 0)
      return tau;
    for (unsigned int iteration = 0; iteration < 10; ++iteration)
      {
        const double speed = std::max({prescribed_speed(time),
                                       prescribed_speed(time + tau / 2),
                                       prescribed_speed(time + tau)});
        const double allowed =
          parameters.target_cfl * levels.finest_cell_size / speed;
        if (speed == 0 || tau <= allowed * (1 + 1e-12))
          break;
        tau = allowed;
      }
    return tau;
  }

  template <int dim>
  RunEnd
  Simulator<dim>::run()
  {
    pcout << "vefs: " << dim << "D " << description() << " on "
          << Utilities::MPI::n_mpi_processes(comm) << " MPI rank(s), output in "
          << parameters.output_directory << "/" << std::endl;
    StepStatistics<dim> statistics;
    {
      TimerOutput::Scope scope(timer, "initial state");
      make_cavity();
      if (checkpoint.empty())
        set_initial_state();
      else
        statistics = resume();
    }

    LiquidDomain<dim> domain(fields);
    if (!prescribed_velocity)
      flow.setup(domain, statistics.time);
    // A resumed run has the row of its first step already.
    if (checkpoint.empty())
      report(statistics, domain);
    else
      pcout << "resumed at step " << statistics.step
            << " (t = " << statistics.time << ") from " << checkpoint << "/"
            << std::endl;

    for (unsigned int steps_done = 1; !is_last_step(statistics); ++steps_done)
      {
        const StepLength step_length = choose_step_length(statistics);
        const double     tau         = step_length.tau;
        const double     cfl =
          tau * statistics.max_velocity / levels.finest_cell_size;
        // Checked before the step, while the state is still good.
        const std::string problem = step_problem(parameters,
                                                 statistics.step + 1,
                                                 tau,
                                                 step_length.controlled,
                                                 cfl,
                                                 statistics.max_velocity);
        if (!problem.empty())
          stop(statistics.step + 1, statistics, problem, domain, true);
        ++statistics.step;
        statistics.tau          = tau;
        statistics.cfl          = cfl;
        statistics.mesh_changes = 0;
        // The next step moves the surface about as far as this one.
        const double expected_cfl =
          std::max(parameters.target_cfl, statistics.cfl);

        // 1. Advection: phi and u along the characteristics; between
        // remaps the level set from the last remap through all steps since.
        // The velocity at mid-step keeps the trace of a prescribed one
        // second order.
        if (prescribed_velocity)
          prescribed_velocity->set_time(statistics.time + tau / 2);
        if (parameters.band_predicted)
          {
            // Refine where the surface will be before it gets there: the
            // band need not be widened by the CFL number.
            typename TransportedFields<dim>::VectorType surface_ahead;
            {
              TimerOutput::Scope scope(timer, "1 advection: predict");
              if (prescribed_velocity)
                fields.set_velocity(*prescribed_velocity);
              surface_ahead = predict_level_set(fields, tau, *locator);
            }
            TimerOutput::Scope scope(timer, "1 advection: refine ahead");
            statistics.mesh_changes +=
              refine_ahead_of_surface(triangulation,
                                      fields,
                                      levels,
                                      levels.max_level - levels.min_level,
                                      parameters.level_set_interpolation,
                                      surface_ahead,
                                      parameters.band_in_one_change);
            statistics.advected_cells = triangulation.n_global_active_cells();
          }
        bool remap = true;
        {
          TimerOutput::Scope scope(timer, "1 advection");
          if (prescribed_velocity)
            fields.set_velocity(*prescribed_velocity);
          level_set_history.add_step(fields, tau);
          advect_along_characteristics(
            fields,
            tau,
            *locator,
            FootInterpolation(parameters, rheology.shear_modulus()));
          fields.coarsened_detail.clear();
          if (level_set_history.enabled())
            {
              level_set_history.compose(fields,
                                        *locator,
                                        parameters.level_set_interpolation);
              remap = level_set_history.remap_due(statistics.cfl, expected_cfl);
            }
          if (remap && parameters.redistancing_interval > 0 &&
              statistics.step % parameters.redistancing_interval == 0)
            redistance(fields, parameters.level_set_interpolation);
          if (parameters.volume_correction)
            {
              const double shift = correct_volume(fields, expected_volume);
              if (!remap)
                level_set_history.shift_base(fields, shift);
            }
        }

        // 2. Mesh: refine around the new free surface (at remaps), mark
        // liquid cells. Refined and coarsened in one change before the
        // advection, the mesh changes again only where the surface left the
        // finest cells in more than 'Band miss tolerance' of its cells.
        {
          TimerOutput::Scope scope(timer, "2 mesh adaptation");
          const SurfaceCells surface =
            count_surface_cells(fields, parameters.max_level);
          statistics.coarse_surface_cells = surface.coarse;
          if (remap &&
              (!parameters.band_in_one_change ||
               surface.coarse > parameters.band_miss_tolerance * surface.total))
            {
              levels.expect_cfl(
                std::max(expected_cfl,
                         level_set_history.cells_between_remaps()));
              if (adapt_mesh(triangulation,
                             fields,
                             levels,
                             1,
                             parameters.level_set_interpolation))
                ++statistics.mesh_changes;
              level_set_history.remap(fields);
            }
          domain = LiquidDomain<dim>(fields);
        }

        // 3. Diffusion: the Stokes-like step on the liquid cells, then
        // (with a stress) 4. the stress update.
        if (prescribed_velocity)
          {
            prescribed_velocity->set_time(statistics.time + tau);
            fields.set_velocity(*prescribed_velocity);
          }
        else
          {
            std::string failure;
            try
              {
                diffusion_step(domain,
                               statistics.time + tau,
                               tau,
                               expected_cfl,
                               statistics);
              }
            catch (const SolverError &error)
              {
                failure = error.what();
              }
            if (!failure.empty())
              stop(statistics.step, statistics, failure, domain, false);
            expected_volume -= tau * flow.outflow_rate();
          }

        statistics.time += tau;
        report(statistics, domain);
        if (const auto end = checkpoint_if_due(statistics, steps_done))
          return *end;
      }
    return {};
  }

  template <int dim>
  void
  Simulator<dim>::diffusion_step(const LiquidDomain<dim> &domain,
                                 const double             new_time,
                                 const double             tau,
                                 const double             expected_cfl,
                                 StepStatistics<dim>     &statistics)
  {
    statistics.linear_iterations = 0;
    {
      TimerOutput::Scope scope(timer, "3 diffusion: setup");
      flow.setup(domain, new_time);
    }
    {
      TimerOutput::Scope scope(timer, "3 diffusion: assembly");
      flow.assemble(fields, tau);
    }
    {
      TimerOutput::Scope scope(timer, "3 diffusion: preconditioner");
      flow.build_preconditioner();
    }
    // Contact walls: solve again while the contact set changes (doc/method.md,
    // "Walls"); a few times at the most. Until a solve leaves the set
    // unchanged the solves only have to tell which nodes touch: loosely;
    // the step ends with a full solve that leaves the set unchanged too.
    bool full_solve =
      !flow.touches_contact_walls() ||
      parameters.contact_solver_tolerance <= parameters.solver_tolerance;
    for (unsigned int solves = 1;; ++solves)
      {
        {
          TimerOutput::Scope scope(timer, "3 diffusion: solve");
          statistics.linear_iterations +=
            flow.solve(full_solve ? parameters.solver_tolerance
                                  : parameters.contact_solver_tolerance);
        }
        if (full_solve && solves >= max_contact_iterations)
          break;
        bool changed;
        {
          TimerOutput::Scope scope(timer, "3 diffusion: contact set");
          changed = flow.update_contact(fields, tau);
        }
        if (!changed && full_solve)
          break;
        if (!changed || solves + 1 >= max_contact_iterations)
          full_solve = true;
      }
    {
      // The next characteristics trace back through the band around the
      // liquid: give it the new velocity, as far as the surface can move.
      TimerOutput::Scope scope(timer, "velocity extension");
      typename TransportedFields<dim>::VectorType known;
      fields.initialize_vector(known);
      // With 'Stress theta' < 1 the stress law sees theta u + (1 - theta) u*:
      // keep u* before the new velocity replaces it.
      const double theta = rheology.implicit_weight();
      typename TransportedFields<dim>::VectorType blended_velocity;
      if (rheology.has_stress() && theta < 1)
        {
          fields.initialize_vector(blended_velocity);
          blended_velocity = fields.fields;
        }
      flow.copy_velocity_to(fields, known);
      if (rheology.has_stress())
        {
          TimerOutput::Scope scope(timer, "4 stress update");
          if (theta < 1)
            {
              blended_velocity.sadd(1 - theta, theta, fields.fields);
              blended_velocity.update_ghost_values();
            }
          const StressUpdateReport report =
            update_stress(fields,
                          theta < 1 ? blended_velocity : fields.fields,
                          domain,
                          rheology,
                          tau,
                          parameters.extend_outside_stress);
          statistics.max_velocity_gradient = report.max_velocity_gradient;
          statistics.strain_limited_points = report.strain_limited_points;
        }
      const unsigned int layers =
        std::max<unsigned int>(parameters.extension_layers,
                               std::ceil(expected_cfl) + 2);
      // The vertices of cut cells outside the liquid keep the flow step's
      // velocity and the updated stress, or take the extension ('Outside
      // velocity/stress of cut cells').
      const bool extend_stress =
        fields.has_stress() && parameters.extend_outside_stress;
      if (parameters.extend_outside_velocity == extend_stress)
        {
          if (extend_stress)
            unflag_nodes_outside_liquid(fields, known);
          extend_flow_fields(fields, known, layers, flow_components(fields));
        }
      else
        {
          auto known_outside_too = known;
          unflag_nodes_outside_liquid(fields, known);
          extend_flow_fields(fields,
                             extend_stress ? known_outside_too : known,
                             layers,
                             velocity_components<dim>());
          if (fields.has_stress())
            extend_flow_fields(fields,
                               extend_stress ? known : known_outside_too,
                               layers,
                               stress_components(fields));
        }
    }
  }

  template <int dim>
  void
  Simulator<dim>::report(StepStatistics<dim>     &statistics,
                         const LiquidDomain<dim> &domain)
  {
    {
      TimerOutput::Scope scope(timer, "postprocessing");
      measure_step(parameters,
                   fields,
                   domain,
                   initial_volume,
                   expected_volume,
                   statistics);
      statistics.dofs            = flow.n_dofs();
      statistics.contact_force   = flow.contact_force();
      statistics.contact_measure = flow.contact_measure();
      if (rheology.has_stress())
        {
          const StressMeasure stress = measure_stress(fields, domain, rheology);
          statistics.elastic_energy  = stress.elastic_energy;
          statistics.min_conformation_eigenvalue =
            stress.min_conformation_eigenvalue;
          statistics.non_positive_conformation_points =
            stress.non_positive_points;
        }
      if (!parameters.probe_point.empty())
        statistics.probe_velocity =
          probe_velocity(fields,
                         *locator,
                         to_point<dim>(parameters.probe_point));
      if (exact_final_level_set)
        {
          // Only the final shape is known exactly.
          statistics.shape_error =
            is_last_step(statistics)
              ? shape_error(fields, *exact_final_level_set)
              : std::numeric_limits<double>::quiet_NaN();
          statistics.interface_thickness =
            interface_thickness(fields, levels.finest_cell_size);
        }
      statistics.wall_time = wall_time_offset + wall_clock.wall_time();
    }
    {
      TimerOutput::Scope scope(timer, "health check");
      const std::string  problem =
        state_problem(parameters,
                      fields,
                      statistics,
                      statistics_file.non_finite_column(statistics));
      if (!problem.empty())
        stop(statistics.step, statistics, problem, domain, false);
    }
    statistics_file.write(statistics);

    if (is_output_step(statistics))
      {
        TimerOutput::Scope scope(timer, "output");
        visualization.write(fields, flow, domain.fractions(), statistics.time);
        last_output_step = statistics.step;
      }

    if (statistics.step == 0)
      return;
    const double per_step = statistics.wall_time / statistics.step;
    const double left =
      per_step * (parameters.end_time - statistics.time) / statistics.tau;
    pcout << "step " << std::setw(5) << statistics.step << "  t "
          << std::setprecision(4) << std::setw(10) << statistics.time
          << "  CFL " << std::setw(6) << statistics.cfl << "  its "
          << std::setw(3) << statistics.linear_iterations << "  dV/V "
          << std::setw(10) << statistics.volume_change << "  cells "
          << std::setw(7) << statistics.cells << "  " << std::setprecision(3)
          << per_step << " s/step  ~" << std::setprecision(3) << left
          << " s left" << std::endl;
  }

  template <int dim>
  void
  Simulator<dim>::stop(const unsigned int         step,
                       const StepStatistics<dim> &statistics,
                       const std::string         &problem,
                       const LiquidDomain<dim>   &domain,
                       const bool                 state_is_good)
  {
    // Keep the state the run ended with for a look, if it can be shown.
    const bool written = state_is_good && last_output_step == statistics.step;
    if (!written && fields_are_finite(fields))
      visualization.write(fields, flow, domain.fractions(), statistics.time);
    std::string what = problem;
    while (!what.empty() && what.back() == '.')
      what.pop_back();
    std::ostringstream message;
    message << "step " << step << " (t = " << statistics.time << "): " << what;
    if (step > 0)
      message << ". The statistics end with step " << step - 1;
    if (!visualization.last_file().empty())
      message << ", the visualization with " << parameters.output_directory
              << "/" << visualization.last_file()
              << (state_is_good ? " (the last good state)"
                                : " (the last finite state)");
    message << ".";
    throw SolverError(message.str());
  }

  template <int dim>
  std::string
  Simulator<dim>::description() const
  {
    if (prescribed_velocity)
      return "transport with a prescribed velocity";
    switch (parameters.regime())
      {
        case Regime::newtonian:
          return "Newtonian free-surface flow";
        case Regime::oldroyd_b:
          return "Oldroyd-B free-surface flow";
        case Regime::elastic_solid:
          return parameters.solvent_viscosity > 0
                   ? "Kelvin-Voigt elastic solid (neo-Hookean + viscous)"
                   : "neo-Hookean elastic solid";
      }
    return "";
  }

  template class Simulator<2>;
  template class Simulator<3>;
} // namespace vefs
