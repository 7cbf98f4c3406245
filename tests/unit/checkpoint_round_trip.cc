// The checkpoint (checkpoint.h) round trip: write_checkpoint() of an
// adaptively refined mesh, the fields with stress, the level set gradient,
// a level set history with a base and two steps, and a run state; then
// read_checkpoint() into a fresh triangulation holding the coarse mesh
// only. Every vector (owned and ghost entries), every history scalar and
// every state entry must come back bit for bit. Also: a checkpoint with a
// damaged file is refused with a CheckpointError on all ranks. 2D and 3D,
// 1 and 2 ranks (read on as many ranks as written).

#include "unit_test.h"

#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/grid/grid_generator.h>

#include <vefs/io/checkpoint.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>

using namespace dealii;

namespace
{
  /** As the simulator makes it (simulator.cc): the coarse mesh only. */
  template <int dim>
  std::unique_ptr<parallel::distributed::Triangulation<dim>>
  make_coarse_mesh()
  {
    auto triangulation =
      std::make_unique<parallel::distributed::Triangulation<dim>>(
        MPI_COMM_WORLD,
        Triangulation<dim>::limit_level_difference_at_vertices,
        parallel::distributed::Triangulation<
          dim>::mesh_reconstruction_after_repartitioning);
    Point<dim> lower, upper;
    for (unsigned int d = 0; d < dim; ++d)
      upper[d] = 1 + 0.5 * d;
    GridGenerator::subdivided_hyper_rectangle(*triangulation,
                                              std::vector<unsigned int>(dim, 2),
                                              lower,
                                              upper,
                                              true);
    return triangulation;
  }

  using VectorType = LinearAlgebra::distributed::Vector<double>;

  /** Entries (owned and ghost) that differ; -1 if the layouts differ. */
  int
  n_different(const VectorType &a, const VectorType &b)
  {
    if (a.locally_owned_size() != b.locally_owned_size() ||
        a.get_partitioner()->n_ghost_indices() !=
          b.get_partitioner()->n_ghost_indices() ||
        !(a.locally_owned_elements() == b.locally_owned_elements()) ||
        !(a.get_partitioner()->ghost_indices() ==
          b.get_partitioner()->ghost_indices()))
      return -1;
    int n = 0;
    for (unsigned int i = 0;
         i < a.locally_owned_size() + a.get_partitioner()->n_ghost_indices();
         ++i)
      // Bit for bit: NaN and signed zeros included.
      {
        const double x = a.local_element(i), y = b.local_element(i);
        if (std::memcmp(&x, &y, sizeof(double)) != 0)
          ++n;
      }
    return n;
  }

  template <int dim>
  void
  check(std::ostream &out)
  {
    const MPI_Comm    comm      = MPI_COMM_WORLD;
    const std::string directory = "output_" + std::to_string(dim) + "d";
    const std::string name      = std::to_string(dim) + "D, ";
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      std::filesystem::create_directories(directory);

    auto triangulation = make_coarse_mesh<dim>();
    triangulation->refine_global(2);
    for (unsigned int cycle = 0; cycle < 2; ++cycle)
      {
        for (const auto &cell : triangulation->active_cell_iterators())
          if (cell->is_locally_owned() && cell->center()[0] < 0.3 + 0.1 * cycle)
            cell->set_refine_flag();
        triangulation->execute_coarsening_and_refinement();
      }
    vefs::TransportedFields<dim> fields(*triangulation, true, false, {});
    fields.setup_dofs();
    const unsigned int n_stress =
      vefs::TransportedFields<dim>::n_stress_components;
    const unit_test::Smooth<dim> level_set(1, 0.1);
    fields.interpolate(
      level_set,
      unit_test::Smooth<dim>(dim, 0.2),
      std::make_unique<unit_test::Smooth<dim>>(n_stress, 0.3).get());
    vefs::LevelSetGradient<dim> gradient;
    gradient.interpolate(fields, level_set);
    vefs::LevelSetHistory<dim> history(1.5);
    history.remap(fields, gradient);
    fields.set_velocity(unit_test::Smooth<dim>(dim, 0.4));
    history.add_step(fields, 0.01);
    fields.set_velocity(unit_test::Smooth<dim>(dim, 0.5));
    history.add_step(fields, 1. / 3);
    history.remap_due(0.1 / 3, 0.2);

    vefs::RunState<dim> state;
    state.statistics.step                  = 17;
    state.statistics.time                  = 0.1 + 1. / 7;
    state.statistics.tau                   = 1. / 3;
    state.statistics.cfl                   = M_PI;
    state.statistics.max_velocity          = std::sqrt(2.);
    state.statistics.max_velocity_gradient = 1e-300;
    state.statistics.linear_iterations     = 123456;
    state.statistics.wall_time             = 98.7654321;
    state.initial_volume                   = 1. / 9;
    state.expected_volume                  = 1. / 11;
    state.last_output_step                 = 15;
    state.visualization_series             = {{0., "solution-00000.pvtu"},
                                              {0.1 / 3, "solution-00015.pvtu"}};

    const std::string problem = vefs::write_checkpoint(directory,
                                                       "set Dimension = 2\n",
                                                       fields,
                                                       gradient,
                                                       history,
                                                       state);
    out << name
        << "write_checkpoint: " << (problem.empty() ? "no problem" : problem)
        << '\n';
    const std::string found = vefs::find_checkpoint(directory, comm);
    out << name << "found: " << found << '\n';

    auto                         fresh_mesh = make_coarse_mesh<dim>();
    vefs::TransportedFields<dim> fresh(*fresh_mesh, true, false, {});
    vefs::LevelSetGradient<dim>  fresh_gradient;
    vefs::LevelSetHistory<dim>   fresh_history(1.5);
    const vefs::RunState<dim>    read = vefs::read_checkpoint(found,
                                                           *fresh_mesh,
                                                           fresh,
                                                           fresh_gradient,
                                                           fresh_history);

    out << name << "active cells: " << triangulation->n_global_active_cells()
        << " written, " << fresh_mesh->n_global_active_cells() << " read\n";
    int n_wrong_nodes = fields.nodes().size() == fresh.nodes().size() ? 0 : 1;
    for (unsigned int i = 0; n_wrong_nodes == 0 && i < fields.nodes().size();
         ++i)
      if (fields.nodes()[i].point != fresh.nodes()[i].point ||
          fields.nodes()[i].dofs.first != fresh.nodes()[i].dofs.first)
        ++n_wrong_nodes;
    out << name << "ranks whose nodes differ: "
        << Utilities::MPI::sum(n_wrong_nodes, comm) << '\n';

    const auto sum_differences = [&](const VectorType &a, const VectorType &b) {
      const int n = n_different(a, b);
      return Utilities::MPI::min(n, comm) < 0
               ? std::string("layouts differ")
               : std::to_string(Utilities::MPI::sum(n, comm));
    };
    out << name << "entries different, fields: "
        << sum_differences(fields.vector(), fresh.vector())
        << ", level set gradient: "
        << sum_differences(gradient.vector(), fresh_gradient.vector()) << '\n';
    const auto kept = history.vectors(), restored = fresh_history.vectors();
    out << name << "history vectors: " << kept.size() << " written, "
        << restored.size() << " read\n";
    std::string history_differences;
    for (unsigned int i = 0; i < std::min(kept.size(), restored.size()); ++i)
      history_differences += " " + sum_differences(*kept[i], *restored[i]);
    out << name
        << "entries different per history vector:" << history_differences
        << '\n';
    const auto scalars       = history.scalars(),
               fresh_scalars = fresh_history.scalars();
    out << name << "history scalars equal: "
        << (scalars.has_base == fresh_scalars.has_base &&
                scalars.moved == fresh_scalars.moved &&
                scalars.taus == fresh_scalars.taus
              ? "yes"
              : "no")
        << '\n';

    const auto &s = state.statistics, &r = read.statistics;
    const bool  state_equal =
      s.step == r.step && s.time == r.time && s.tau == r.tau &&
      s.cfl == r.cfl && s.max_velocity == r.max_velocity &&
      s.max_velocity_gradient == r.max_velocity_gradient &&
      s.linear_iterations == r.linear_iterations &&
      s.wall_time == r.wall_time &&
      state.initial_volume == read.initial_volume &&
      state.expected_volume == read.expected_volume &&
      state.last_output_step == read.last_output_step &&
      state.visualization_series == read.visualization_series;
    out << name << "run state equal: " << (state_equal ? "yes" : "no") << '\n';

    // One byte more in a file the state lists: refused before p4est reads.
    MPI_Barrier(comm);
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      std::ofstream(found + "/parameters.prm", std::ios::app) << ' ';
    MPI_Barrier(comm);
    bool refused = false;
    try
      {
        auto                         mesh = make_coarse_mesh<dim>();
        vefs::TransportedFields<dim> damaged(*mesh, true, false, {});
        vefs::LevelSetGradient<dim>  damaged_gradient;
        vefs::LevelSetHistory<dim>   damaged_history(1.5);
        vefs::read_checkpoint(found,
                              *mesh,
                              damaged,
                              damaged_gradient,
                              damaged_history);
      }
    catch (const vefs::CheckpointError &)
      {
        refused = true;
      }
    out << name << "damaged checkpoint refused on all ranks: "
        << (!Utilities::MPI::logical_or(!refused, comm) ? "yes" : "no") << '\n';
  }
} // namespace

int
main(int argc, char **argv)
{
  return unit_test::run(argc, argv, [](std::ostream &out) {
    check<2>(out);
    check<3>(out);
  });
}
