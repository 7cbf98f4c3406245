#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>

#include <vefs/base/write_failure.h>
#include <vefs/core/health_check.h>
#include <vefs/core/simulator.h>
#include <vefs/flow/flow_velocity.h>
#include <vefs/flow/prescribed_velocity.h>
#include <vefs/io/checkpoint.h>
#include <vefs/stress/dumbbells.h>
#include <vefs/stress/stress.h>
#include <vefs/transport/free_surface.h>
#include <vefs/transport/initial_liquid.h>
#include <vefs/transport/split_subtrees.h>
#include <vefs/transport/subtree_partition.h>

#include <cmath>
#include <iomanip>
#include <iostream>
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

    /**
     * Whether the health check watches the energy (EnergyWatch): a solid or
     * an Oldroyd-B liquid, whose elastic wave the time step may not resolve,
     * in a scene that nothing supplies with energy: a flow (not a
     * prescribed velocity) without 'velocity' walls and without gravity
     * along a periodic direction (the liquid falls there for ever).
     */
    bool
    energy_is_watched(const Parameters &parameters)
    {
      bool source = parameters.transport.velocity_is_prescribed();
      for (const WallType type : parameters.cavity.wall_type)
        source = source || type == WallType::velocity;
      for (const unsigned int d : parameters.cavity.periodic_directions())
        source = source || parameters.material.gravity[d] != 0;
      return !source && parameters.material.regime() != Regime::newtonian;
    }

    /**
     * How the local mesh follows p4est's after a mesh change. In 3D it is
     * rebuilt from the coarse cells instead of being refined and coarsened
     * until it matches: fewer passes on several ranks, and the cells lie in
     * memory in p4est's order (the space-filling curve), which every loop
     * over them gains from (doc/bouncing_ball_3d_study.md, "Settings of the
     * fine scenes"); the 3D deformation's advection gains from the order as
     * much as its adaptation loses (L = 5, CFL 5: 31.0 + 14.2 s against
     * 35.8 + 11.4 s). In 2D the rebuild, a pass per level, costs more than
     * it gains: Zalesak's disk at h = 1/128, CFL 10, adaptation 4.8 s
     * against 2.2 s (doc/transport.md); the 2D stiff ball to t = 0.3 s
     * (a mesh change every step, 3,000 cells), adaptation 5.8 s against 3.7
     * s on one rank, 3.6 s against 2.3 s on two (the same meshes).
     */
    template <int dim>
    typename parallel::distributed::Triangulation<dim>::Settings
    mesh_settings()
    {
      return dim == 2
               ? parallel::distributed::Triangulation<dim>::default_setting
               : parallel::distributed::Triangulation<
                   dim>::mesh_reconstruction_after_repartitioning;
    }
  } // namespace

  template <int dim>
  Simulator<dim>::Simulator(const Parameters       &parameters,
                            const ParameterHandler &prm,
                            const std::string      &checkpoint)
    : parameters(parameters)
    , parameters_text(printed(prm))
    , checkpoint(checkpoint)
    , rheology(parameters.material,
               parameters.stress,
               parameters.time.max_strain_per_step,
               parameters.time.second_order)
    , comm(MPI_COMM_WORLD)
    , output(parameters.output_directory, comm, !checkpoint.empty())
    , pcout(std::cout,
            parameters.output.verbose &&
              Utilities::MPI::this_mpi_process(comm) == 0)
    , timer(comm,
            pcout,
            parameters.output.verbose ? TimerOutput::summary
                                      : TimerOutput::never,
            TimerOutput::wall_times)
    , triangulation(comm,
                    Triangulation<dim>::limit_level_difference_at_vertices,
                    mesh_settings<dim>())
    , cavity(std::make_pair(to_point<dim>(parameters.cavity.cavity_lower),
                            to_point<dim>(parameters.cavity.cavity_upper)))
    , levels(parameters.mesh,
             parameters.cavity,
             dim,
             parameters.time.target_cfl)
    , time(parameters.time,
           parameters.output,
           parameters.material.gravity,
           levels.finest_cell_size)
    , fields(triangulation,
             rheology.has_stress(),
             parameters.time.second_order,
             parameters.cavity.periodic_directions(),
             parameters.material.has_dumbbells()
               ? parameters.material.dumbbell_fields
               : 0)
    , flow(parameters.flow_step(), rheology, triangulation)
    , statistics_file(output.path(), comm, !checkpoint.empty())
    , visualization(parameters.output_directory)
    , energy_watch(energy_is_watched(parameters),
                   parameters.material,
                   parameters.cavity)
    , checkpoints(parameters.checkpoint,
                  parameters.output_directory,
                  comm,
                  pcout)
  {
    if (parameters.transport.velocity_is_prescribed())
      velocity = std::make_unique<PrescribedVelocity<dim>>(
        parameters.transport.prescribed_velocity);
    else
      velocity = std::make_unique<FlowVelocity<dim>>(parameters.flow_step(),
                                                     rheology,
                                                     flow,
                                                     timer);
    if (!parameters.transport.exact_final_level_set.empty())
      exact_final_level_set = make_exact_final_level_set<dim>(
        parameters.transport.exact_final_level_set,
        parameters.initial_liquid,
        parameters.cavity);
    std::string problem;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        problem =
          checked_write(parameters.output_directory + "/parameters.prm",
                        [&](std::ostream &out) { out << parameters_text; });
      }
    throw_if_write_failed(problem, "before the first step", comm);
  }

  template <int dim>
  RunEnd
  Simulator<dim>::run()
  {
    LiquidDomain<dim> domain = start();
    for (unsigned int steps_done = 1; !time.finished(); ++steps_done)
      {
        // 1. The step's length, from the speeds of the last one.
        start_step(domain);
        // 2.-4. Every field along the characteristics; the level set
        // redistanced and corrected to the expected volume.
        surface->advect(fields, *velocity, time, statistics);
        // 5.-6. The mesh adapted to the new surface; its liquid domain.
        domain = surface->adapt_mesh(fields, time, statistics);
        // 7.-9. The new velocity (and stress) on the liquid domain, extended
        // beyond it.
        advance_velocity(domain);
        time.end_step();
        report(domain);
        // 10. What the new velocity carries out through open walls leaves
        // the volume the next advection keeps (after report(): this step's
        // volume_change compares with this step's expected volume).
        surface->remove_outflow(velocity->outflow(time.tau()));
        if (const auto end = checkpoint_if_due(steps_done))
          return *end;
      }
    return {};
  }

  template <int dim>
  LiquidDomain<dim>
  Simulator<dim>::start()
  {
    pcout << "vefs: " << dim << "D " << velocity->description() << " on "
          << Utilities::MPI::n_mpi_processes(comm) << " MPI rank(s), output in "
          << parameters.output_directory << "/" << std::endl;
    {
      TimerOutput::Scope scope(timer, "initial state");
      make_cavity();
      surface = std::make_unique<SurfaceTracker<dim>>(
        parameters.mesh,
        parameters.transport,
        FootInterpolation(parameters.transport,
                          rheology.has_stress(),
                          rheology.shear_modulus()),
        triangulation,
        levels,
        *locator,
        timer);
      add_scene_columns();
      if (checkpoint.empty())
        set_initial_state();
      else
        resume();
    }
    LiquidDomain<dim> domain(fields);
    // The second-order scheme's first flow solve (the initial
    // acceleration) fails like a step's: with the state kept for a look.
    stop_on_solver_error(
      [&]() {
        velocity->start(fields, domain, time.time(), checkpoint.empty());
      },
      "the initial acceleration: ",
      domain,
      true);
    // A resumed run has the row of its first step already.
    if (checkpoint.empty())
      report(domain);
    else
      pcout << "resumed at step " << time.step() << " (t = " << time.time()
            << ") from " << checkpoint << "/" << std::endl;
    return domain;
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
        statistics_file.add_column("elastic_wave_number", [](const auto &s) {
          return s.elastic_wave_number;
        });
        statistics_file.add_column("min_conformation_eigenvalue",
                                   [](const auto &s) {
                                     return s.min_conformation_eigenvalue;
                                   });
        statistics_file.add_column("non_positive_conformation_points",
                                   [](const auto &s) {
                                     return s.non_positive_conformation_points;
                                   });
      }
    velocity->add_columns(statistics_file);
    surface->add_columns(statistics_file);
    if (!parameters.postprocess.probe_point.empty())
      {
        for (unsigned int d = 0; d < dim; ++d)
          statistics_file.add_column(std::string("probe_u_") + "xyz"[d],
                                     [d](const auto &s) {
                                       return s.probe_velocity[d];
                                     });
        if (rheology.has_stress())
          for (unsigned int i = 0;
               i < TransportedFields<dim>::n_stress_components;
               ++i)
            {
              const auto index =
                SymmetricTensor<2, dim>::unrolled_to_component_indices(i);
              const std::string name =
                std::string("probe_sigma_") + "xyz"[index[0]] + "xyz"[index[1]];
              statistics_file.add_column(name, [i](const auto &s) {
                return s.probe_stress.access_raw_entry(i);
              });
              if (parameters.material.has_dumbbells())
                statistics_file.add_column(name + "_error", [i](const auto &s) {
                  return s.probe_stress_error.access_raw_entry(i);
                });
            }
      }
  }

  template <int dim>
  void
  Simulator<dim>::make_cavity()
  {
    std::vector<unsigned int> subdivisions(
      parameters.cavity.coarse_subdivisions.begin(),
      parameters.cavity.coarse_subdivisions.end());
    // colorize: boundary ids 0..2dim-1 for the walls x-, x+, y-, y+, z-, z+.
    GridGenerator::subdivided_hyper_rectangle(
      triangulation,
      subdivisions,
      cavity.get_boundary_points().first,
      cavity.get_boundary_points().second,
      true);
    for (const unsigned int d : parameters.cavity.periodic_directions())
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
    const auto cell_weight =
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
    };
    // Flow elements two or more levels coarser than the finest cells need
    // their cells on one rank (FlowElements); p4est keeps families of one
    // level together by itself.
    if (parameters.flow.flow_level_offset >= 2)
      levels.subtree_level = static_cast<int>(parameters.mesh.max_level) -
                             parameters.flow.flow_level_offset;
    SubtreePartition<dim>(levels.subtree_level, cell_weight)
      .connect_to(triangulation);
    locator =
      std::make_unique<BoxMeshLocator<dim>>(triangulation,
                                            cavity,
                                            subdivisions,
                                            parameters.cavity.wall_type);
  }

  template <int dim>
  void
  Simulator<dim>::set_initial_state()
  {
    const auto level_set =
      make_initial_level_set<dim>(parameters.initial_liquid, parameters.cavity);
    const auto initial_velocity =
      make_initial_velocity<dim>(parameters.initial_liquid);
    const auto stress = make_initial_stress<dim>(parameters.initial_liquid);
    triangulation.refine_global(parameters.mesh.min_level);
    fields.setup_dofs();
    // Refine toward the initial surface, evaluating it exactly on each mesh.
    // A level set whose slope varies may make a cell and its children want
    // different levels: the cycles are bounded.
    for (unsigned int cycle = 0;; ++cycle)
      {
        fields.interpolate(*level_set, *initial_velocity, stress.get());
        if (cycle == parameters.mesh.max_level ||
            !adapt_mesh<dim>(triangulation,
                             fields,
                             nullptr,
                             levels,
                             LevelSetInterpolation::linear))
          break;
      }
    if (parameters.material.has_dumbbells())
      set_initial_dumbbells(fields,
                            rheology,
                            parameters.material.dumbbell_seed,
                            parameters.material.dumbbell_variance_reduction);
    velocity->set_initial_velocity(fields);
    const double initial_volume = sharp_liquid_volume(fields, 0).volume;
    surface->start(fields, *level_set, initial_volume);
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
  void
  Simulator<dim>::resume()
  {
    const RunState<dim> state = read_checkpoint(checkpoint,
                                                triangulation,
                                                fields,
                                                surface->gradient(),
                                                surface->history());
    // Loaded on another number of ranks, p4est's partition counts cells and
    // may cut a flow element.
    mend_split_subtrees(triangulation,
                        levels.subtree_level,
                        fields,
                        surface->gradient(),
                        surface->history());
    surface->resume(state.initial_volume, state.expected_volume);
    last_output_step = state.last_output_step;
    wall_time_offset = state.statistics.wall_time;
    visualization.resume(state.visualization_series);
    statistics_file.resume(state.statistics.step);
    statistics = state.statistics;
    flow.resume_contact(state.contact_state);
    time.resume(statistics.step, statistics.time, statistics.tau);
    pcout << "resumed at step " << statistics.step
          << " (t = " << statistics.time << ") from " << checkpoint << "/"
          << std::endl;
  }

  template <int dim>
  void
  Simulator<dim>::start_step(const LiquidDomain<dim> &domain)
  {
    const TimeStep step =
      time.landed(velocity->time_step(time, statistics, fields));
    const double cfl = time.cfl_of(step.tau, statistics.max_velocity);
    // Checked before the step, while the state is still good.
    const std::string problem = step_problem(parameters.health_check,
                                             parameters.time,
                                             time.step() + 1,
                                             step.tau,
                                             step.controlled,
                                             cfl,
                                             statistics.max_velocity,
                                             parameters.flow.flow_level_offset);
    if (!problem.empty())
      stop(time.step() + 1, problem, domain, true);
    time.start_step(step.tau, statistics.max_velocity);
  }

  template <int dim>
  void
  Simulator<dim>::advance_velocity(const LiquidDomain<dim> &domain)
  {
    stop_on_solver_error(
      [&]() { velocity->advance(fields, domain, time, statistics); },
      "",
      domain,
      false);
  }

  template <int dim>
  std::optional<RunEnd>
  Simulator<dim>::checkpoint_if_due(const unsigned int steps_done)
  {
    if (time.finished())
      return {};
    return checkpoints.after_step(time.step(), time.time(), steps_done, [&]() {
      TimerOutput::Scope  scope(timer, "checkpoint");
      const RunState<dim> state{statistics,
                                surface->initial_volume(),
                                surface->expected_volume(),
                                last_output_step,
                                visualization.get_series(),
                                flow.contact_state()};
      return write_checkpoint(parameters.output_directory,
                              parameters_text,
                              fields,
                              surface->gradient(),
                              surface->history(),
                              state);
    });
  }

  template <int dim>
  void
  Simulator<dim>::report(const LiquidDomain<dim> &domain)
  {
    statistics.step = time.step();
    statistics.time = time.time();
    statistics.tau  = time.tau();
    statistics.cfl  = time.cfl();
    {
      TimerOutput::Scope scope(timer, "postprocessing");
      measure_step(parameters.material,
                   parameters.cavity,
                   fields,
                   domain,
                   surface->initial_volume(),
                   surface->expected_volume(),
                   statistics);
      velocity->measure(statistics);
      if (rheology.has_stress())
        {
          const StressMeasure stress = measure_stress(fields, domain, rheology);
          statistics.elastic_energy  = stress.elastic_energy;
          statistics.min_conformation_eigenvalue =
            stress.min_conformation_eigenvalue;
          statistics.non_positive_conformation_points =
            stress.non_positive_points;
          if (stress.non_positive_points > 0)
            {
              // The linear update loses it at large steps; the run goes on
              // (doc/viscoelastic.md, "Positivity").
              warn_once(non_positive_conformation_said, [&]() {
                std::ostringstream what;
                what << "the conformation tensor is not positive definite at "
                     << stress.non_positive_points
                     << " quadrature points (smallest eigenvalue "
                     << stress.min_conformation_eigenvalue
                     << "; columns non_positive_conformation_points and "
                        "min_conformation_eigenvalue): "
                     << (parameters.stress.stress_update ==
                             StressUpdate::exponential
                           ? "shorten 'Time/Time step'"
                           : "'Stress/Stress update = exponential' keeps it "
                             "positive definite, or shorten 'Time/Time step'");
                return what.str();
              });
            }
        }
      if (!parameters.postprocess.probe_point.empty())
        {
          const Probe<dim> probe =
            probe_velocity(fields,
                           *locator,
                           to_point<dim>(parameters.postprocess.probe_point),
                           rheology.shear_modulus());
          statistics.probe_velocity     = probe.velocity;
          statistics.probe_stress       = probe.stress;
          statistics.probe_stress_error = probe.stress_error;
          // The columns are not zeroed outside: say once what they hold.
          if (!probe.in_liquid)
            warn_once(probe_outside_said, []() {
              return std::string(
                "the point of 'Postprocess/Probe point' lies "
                "outside the liquid; then the columns probe_u_* "
                "hold the velocity field there, which outside "
                "the liquid is only the extension the transport "
                "uses (0 beyond the band around the surface)");
            });
        }
      if (exact_final_level_set)
        {
          // Only the final shape is known exactly.
          statistics.shape_error =
            time.finished() ? shape_error(fields, *exact_final_level_set)
                            : std::numeric_limits<double>::quiet_NaN();
          statistics.interface_thickness =
            interface_thickness(fields, levels.finest_cell_size);
        }
      if (rheology.has_stress())
        statistics.elastic_wave_number =
          std::sqrt(rheology.shear_modulus() / parameters.material.density) *
          time.tau() / levels.finest_cell_size;
      if (statistics.elastic_wave_number > trusted_elastic_wave_number)
        warn_once(untrusted_wave_number_said, [&]() {
          std::ostringstream what;
          what << "an elastic wave crosses " << statistics.elastic_wave_number
               << " of the finest cells in a step, beyond the "
               << trusted_elastic_wave_number
               << " up to which the scheme keeps the energy of an "
                  "impact (doc/reliability.md, \"Stiff solids\"); "
                  "shorter steps ('Time/Time step') keep it";
          return what.str();
        });
      statistics.wall_time = wall_time_offset + wall_clock.wall_time();
    }
    {
      TimerOutput::Scope scope(timer, "health check");
      std::string        problem =
        state_problem(parameters.health_check,
                      fields,
                      statistics,
                      statistics_file.non_finite_column(statistics));
      if (problem.empty())
        problem = energy_watch.problem(parameters.health_check, statistics);
      if (!problem.empty())
        stop(statistics.step, problem, domain, false);
    }
    statistics_file.write(statistics);

    if (time.is_output_step())
      {
        TimerOutput::Scope scope(timer, "output");
        visualization.write(fields,
                            flow,
                            domain.fractions(),
                            statistics.step,
                            statistics.time);
        last_output_step = statistics.step;
      }

    if (statistics.step == 0)
      return;
    const double per_step = statistics.wall_time / statistics.step;
    const double left =
      per_step * (time.end() - statistics.time) / statistics.tau;
    pcout << "step " << std::setw(5) << statistics.step << "  t "
          << std::setprecision(4) << std::setw(10) << statistics.time
          << "  CFL " << std::setw(6) << statistics.cfl << "  its "
          << std::setw(3) << statistics.linear_iterations << "  dV/V "
          << std::setw(10) << statistics.volume_change << "  cells "
          << std::setw(7) << statistics.cells << "  " << std::setprecision(3)
          << per_step << " s/step  ~" << std::setprecision(3) << left
          << " s left"
          << (statistics.unsettled_contact_set ? "  contact set unsettled" : "")
          << std::endl;
  }

  template <int dim>
  void
  Simulator<dim>::warn_once(bool                               &said,
                            const std::function<std::string()> &what) const
  {
    if (said)
      return;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      std::cerr << "vefs: warning: step " << time.step()
                << " (t = " << time.time() << "): " << what() << std::endl;
    said = true;
  }

  template <int dim>
  void
  Simulator<dim>::stop_on_solver_error(const std::function<void()> &solve,
                                       const std::string           &context,
                                       const LiquidDomain<dim>     &domain,
                                       const bool state_is_good)
  {
    // stop() throws a SolverError itself: leave the handler first.
    std::string failure;
    try
      {
        solve();
      }
    catch (const SolverError &error)
      {
        failure = context + error.what();
      }
    if (!failure.empty())
      stop(time.step(), failure, domain, state_is_good);
  }

  template <int dim>
  void
  Simulator<dim>::stop(const unsigned int       step,
                       const std::string       &problem,
                       const LiquidDomain<dim> &domain,
                       const bool               state_is_good)
  {
    // Keep the state the run ended with for a look, if it can be shown.
    const bool  written = state_is_good && last_output_step == time.step();
    std::string what    = problem;
    while (!what.empty() && what.back() == '.')
      what.pop_back();
    if (!written && fields_are_finite(fields))
      try
        {
          visualization.write(fields,
                              flow,
                              domain.fractions(),
                              time.step(),
                              time.time());
        }
      catch (const OutputError &error)
        {
          what += " (and the state could not be written: " +
                  std::string(error.what()) + ")";
        }
    std::ostringstream message;
    message << "step " << step << " (t = " << time.time() << "): " << what;
    if (step > 0)
      message << ". The statistics end with step " << step - 1;
    if (!visualization.last_file().empty())
      message << (step > 0 ? ", the visualization with "
                           : ". The visualization ends with ")
              << parameters.output_directory << "/" << visualization.last_file()
              << (state_is_good ? " (the last good state)"
                                : " (the last finite state)");
    message << ".";
    throw SolverError(message.str());
  }

  template class Simulator<2>;
  template class Simulator<3>;
} // namespace vefs
