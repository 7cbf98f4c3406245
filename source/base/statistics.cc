#include <deal.II/base/mpi.h>

#include <vefs/base/errors.h>
#include <vefs/base/statistics.h>
#include <vefs/base/write_failure.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iomanip>
#include <sstream>

namespace vefs
{
  template <int dim>
  StatisticsFile<dim>::StatisticsFile(const std::string &directory,
                                      const MPI_Comm     comm,
                                      const bool         resume)
    : path(directory + "/statistics")
    , comm(comm)
  {
    if (!resume && Utilities::MPI::this_mpi_process(comm) == 0)
      {
        file.open(directory + "/statistics");
        if (!file)
          throw InputError("entry 'Output directory': cannot write '" +
                           directory + "/statistics'");
      }
    using S = StepStatistics<dim>;
    add_column("step", [](const S &s) { return s.step; });
    add_column("time", [](const S &s) { return s.time; });
    add_column("tau", [](const S &s) { return s.tau; });
    add_column("cfl", [](const S &s) { return s.cfl; });
    add_column("volume", [](const S &s) { return s.volume; });
    add_column("volume_change", [](const S &s) { return s.volume_change; });
    for (unsigned int d = 0; d < dim; ++d)
      add_column(std::string("centroid_") + "xyz"[d],
                 [d](const S &s) { return s.centroid[d]; });
    for (unsigned int d = 0; d < dim; ++d)
      add_column(std::string("centroid_velocity_") + "xyz"[d],
                 [d](const S &s) { return s.centroid_velocity[d]; });
    for (unsigned int d = 0; d < dim; ++d)
      {
        add_column(std::string("lower_") + "xyz"[d],
                   [d](const S &s) { return s.liquid_lower[d]; });
        add_column(std::string("upper_") + "xyz"[d],
                   [d](const S &s) { return s.liquid_upper[d]; });
      }
    add_column("kinetic_energy", [](const S &s) { return s.kinetic_energy; });
    add_column("potential_energy",
               [](const S &s) { return s.potential_energy; });
    add_column("elastic_energy", [](const S &s) { return s.elastic_energy; });
    add_column("total_energy", [](const S &s) {
      return s.kinetic_energy + s.potential_energy + s.elastic_energy;
    });
    add_column("max_velocity", [](const S &s) { return s.max_velocity; });
    add_column("floor_extent", [](const S &s) { return s.floor_extent; });
    add_column("wall_height", [](const S &s) { return s.wall_height; });
    add_column("shadow_holes", [](const S &s) { return s.shadow_holes; });
    add_column("cells", [](const S &s) { return s.cells; });
    add_column("liquid_cells", [](const S &s) { return s.liquid_cells; });
    add_column("coarse_surface_cells",
               [](const S &s) { return s.coarse_surface_cells; });
    add_column("mesh_changes", [](const S &s) { return s.mesh_changes; });
    add_column("dofs", [](const S &s) { return s.dofs; });
    add_column("linear_iterations",
               [](const S &s) { return s.linear_iterations; });
    add_column(
      "wall_time",
      [](const S &s) { return s.wall_time; },
      4);
  }

  template <int dim>
  void
  StatisticsFile<dim>::add_column(const std::string &name,
                                  const Reader      &reader,
                                  const unsigned int precision,
                                  const bool         finite_every_step)
  {
    Assert(!header_written, ExcMessage("Columns come before the first row."));
    columns.push_back({name, reader, precision, finite_every_step});
  }

  template <int dim>
  std::string
  StatisticsFile<dim>::non_finite_column(const StepStatistics<dim> &row) const
  {
    for (const auto &column : columns)
      if (column.finite_every_step && !std::isfinite(column.reader(row)))
        return column.name;
    return "";
  }

  template <int dim>
  std::string
  StatisticsFile<dim>::column_header() const
  {
    std::string header = "#";
    for (const auto &column : columns)
      header += ' ' + column.name;
    return header;
  }

  template <int dim>
  void
  StatisticsFile<dim>::resume(const unsigned int step)
  {
    Assert(!header_written, ExcMessage("Resume before the first row."));
    std::string problem;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        std::ifstream            input(path);
        std::vector<std::string> kept;
        bool                     has_header = false, reached = false;
        for (std::string line; !reached && std::getline(input, line);)
          {
            if (line == column_header())
              has_header = true;
            else if (line.empty() || line[0] != '#')
              {
                // The step is the first column.
                const unsigned long row_step =
                  std::strtoul(line.c_str(), nullptr, 10);
                if (row_step > step)
                  break;
                reached = row_step == step;
              }
            kept.push_back(line);
          }
        if (!input.is_open())
          problem = "cannot read '" + path + "'";
        else if (!has_header)
          problem = "'" + path + "' does not have the columns of this scene";
        else if (!reached)
          problem = "'" + path + "' ends before the step " +
                    std::to_string(step) + " of the checkpoint";
        else
          {
            // Into a new file first: a write that fails (a full disk) must
            // not take the rows of the checkpoint with it.
            input.close();
            const std::string next = path + ".new";
            problem = checked_write(next, [&](std::ostream &out) {
              for (const auto &line : kept)
                out << line << '\n';
            });
            std::error_code error;
            if (problem.empty())
              std::filesystem::rename(next, path, error);
            if (error)
              problem = "cannot replace '" + path + "': " + error.message();
            if (problem.empty())
              {
                file.open(path, std::ios::app);
                if (!file)
                  problem = write_failure(path);
              }
            else
              std::filesystem::remove(next, error);
          }
      }
    problem = Utilities::MPI::broadcast(comm, problem, 0);
    if (!problem.empty())
      throw CheckpointError("option --resume: " + problem);
    header_written = true;
  }

  template <int dim>
  void
  StatisticsFile<dim>::write(const StepStatistics<dim> &row)
  {
    // Every rank checks the root's write: all stop alike if it failed.
    std::string problem;
    if (file.is_open())
      problem = write_row(row);
    std::ostringstream where;
    where << "after step " << row.step << " (t = " << row.time << ")";
    throw_if_write_failed(problem, where.str(), comm);
  }

  template <int dim>
  std::string
  StatisticsFile<dim>::write_row(const StepStatistics<dim> &row)
  {
    errno = 0;
    if (!header_written)
      {
        file
          << "# vefs statistics, one row per time step, SI units.\n"
          << "# volume: volume of the liquid domain of the flow step (the "
             "level set's liquid, cut out of the cells); volume_change: (volume - "
             "initial volume - inflow through the walls) / initial volume; "
             "floor_extent: largest x of liquid on the floor; "
             "wall_height: highest liquid on the x- wall; "
             "shadow_holes: area (length in 2D) of the holes in the "
             "liquid seen from above (a sheet torn into a ring); lower_x, "
             "upper_x, ...: the box around the liquid; centroid_velocity_x, "
             "...: mean velocity of the liquid; total_energy: kinetic + "
             "potential + elastic; coarse_surface_cells: cells crossed by "
             "the surface right after the advection that are coarser than "
             "the finest level (0 if the band kept up with the surface); "
             "mesh_changes: changes of the mesh in the step (refinement "
             "ahead of the surface, adaptation after the advection), each "
             "a rebuild of the whole mesh; advected_cells ('Band placement "
             "= predicted' only): cells of the mesh the advection ran on; "
             "contact_force: the normal force of the contact walls on the "
             "liquid over the step (its impulse over the step length); "
             "unsettled_contact_set: 1 where the contact set still changed "
             "after the step's last allowed solve (10), which the step "
             "keeps; stokes_solves: the step's Stokes solves, one per "
             "contact iteration.\n"
          << column_header() << '\n';
        header_written = true;
      }
    for (unsigned int c = 0; c < columns.size(); ++c)
      file << (c == 0 ? "" : " ") << std::setprecision(columns[c].precision)
           << columns[c].reader(row);
    file << std::endl;
    return file ? std::string() : write_failure(path);
  }

  template class StatisticsFile<2>;
  template class StatisticsFile<3>;
} // namespace vefs
