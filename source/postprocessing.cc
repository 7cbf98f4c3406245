#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <vefs/free_surface.h>
#include <vefs/postprocessing.h>

#include <iomanip>

namespace vefs
{
  template <int dim>
  void
  measure_step(const Parameters             &parameters,
               const TransportedFields<dim> &fields,
               const Vector<float>          &liquid_fraction,
               const double                  initial_volume,
               const double                  expected_volume,
               StepStatistics<dim>          &s)
  {
    const MPI_Comm comm =
      fields.dof_handler.get_triangulation().get_communicator();
    const auto measure = measure_liquid(fields);
    s.volume           = measure.volume;
    s.surface_area     = measure.surface_area;
    s.volume_change    = (measure.volume - expected_volume) / initial_volume;
    s.centroid         = measure.first_moment / measure.volume;

    Tensor<1, dim> gravity;
    for (unsigned int d = 0; d < dim; ++d)
      gravity[d] = parameters.gravity[d];

    const QGauss<dim>                quadrature(2);
    FEValues<dim>                    fe_values(fields.mapping,
                            fields.fe,
                            quadrature,
                            update_values | update_quadrature_points |
                              update_JxW_values);
    const FEValuesExtractors::Vector velocity(0);
    std::vector<Tensor<1, dim>>      u(quadrature.size());

    double       kinetic = 0, potential = 0, liquid_volume = 0, max_speed = 0;
    unsigned int liquid_cells = 0;
    for (const auto &cell : fields.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() &&
          is_liquid(liquid_fraction[cell->active_cell_index()]))
        {
          ++liquid_cells;
          liquid_volume += cell->measure();
          fe_values.reinit(cell);
          fe_values[velocity].get_function_values(fields.fields, u);
          for (const unsigned int q : fe_values.quadrature_point_indices())
            {
              kinetic += 0.5 * parameters.density * u[q].norm_square() *
                         fe_values.JxW(q);
              potential -= parameters.density * gravity *
                           fe_values.quadrature_point(q) * fe_values.JxW(q);
            }
          for (const unsigned int v : cell->vertex_indices())
            {
              Tensor<1, dim> vertex_u;
              for (unsigned int d = 0; d < dim; ++d)
                vertex_u[d] = fields.fields(cell->vertex_dof_index(v, d));
              max_speed = std::max(max_speed, vertex_u.norm());
            }
        }
    s.kinetic_energy     = Utilities::MPI::sum(kinetic, comm);
    s.potential_energy   = Utilities::MPI::sum(potential, comm);
    s.elastic_energy     = 0;
    s.liquid_cell_volume = Utilities::MPI::sum(liquid_volume, comm);
    s.liquid_cells       = Utilities::MPI::sum(liquid_cells, comm);
    s.max_velocity       = Utilities::MPI::max(max_speed, comm);

    const unsigned int vertical = dim - 1;
    s.floor_extent              = liquid_extent_on_wall(fields,
                                           2 * vertical,
                                           0,
                                           parameters.cavity_lower[0]);
    s.wall_height               = liquid_extent_on_wall(fields,
                                          0,
                                          vertical,
                                          parameters.cavity_lower[vertical]);
    s.cells = fields.dof_handler.get_triangulation().n_global_active_cells();
  }

  template <int dim>
  StatisticsFile<dim>::StatisticsFile(const std::string &directory,
                                      const MPI_Comm     comm,
                                      const bool         with_shape_error)
    : with_shape_error(with_shape_error)
  {
    if (Utilities::MPI::this_mpi_process(comm) != 0)
      return;
    file.open(directory + "/statistics");
    AssertThrow(file, ExcMessage("Cannot write " + directory + "/statistics"));
    file << "# vefs statistics, one row per time step, SI units.\n"
         << "# volume: liquid volume from phi; volume_change: (volume - "
            "initial volume - inflow through the walls) / initial volume; "
            "floor_extent: largest x of liquid on the floor; "
            "wall_height: highest liquid on the x- wall.\n"
         << "# step time tau cfl volume volume_change liquid_cell_volume "
            "centroid_x centroid_y"
         << (dim == 3 ? " centroid_z" : "")
         << " kinetic_energy potential_energy elastic_energy max_velocity "
            "floor_extent wall_height cells liquid_cells dofs "
            "linear_iterations wall_time"
         << (with_shape_error ? " shape_error interface_thickness" : "")
         << '\n';
  }

  template <int dim>
  void
  StatisticsFile<dim>::write(const StepStatistics<dim> &r)
  {
    if (!file.is_open())
      return;
    file << r.step << ' ' << std::setprecision(10) << r.time << ' ' << r.tau
         << ' ' << r.cfl << ' ' << r.volume << ' ' << r.volume_change << ' '
         << r.liquid_cell_volume;
    for (unsigned int d = 0; d < dim; ++d)
      file << ' ' << r.centroid[d];
    file << ' ' << r.kinetic_energy << ' ' << r.potential_energy << ' '
         << r.elastic_energy << ' ' << r.max_velocity << ' ' << r.floor_extent
         << ' ' << r.wall_height << ' ' << r.cells << ' ' << r.liquid_cells
         << ' ' << r.dofs << ' ' << r.linear_iterations << ' '
         << std::setprecision(4) << r.wall_time;
    if (with_shape_error)
      file << ' ' << std::setprecision(10) << r.shape_error << ' '
           << r.interface_thickness;
    file << std::endl;
  }

  template void
  measure_step<2>(const Parameters &,
                  const TransportedFields<2> &,
                  const Vector<float> &,
                  const double,
                  const double,
                  StepStatistics<2> &);
  template void
  measure_step<3>(const Parameters &,
                  const TransportedFields<3> &,
                  const Vector<float> &,
                  const double,
                  const double,
                  StepStatistics<3> &);
  template class StatisticsFile<2>;
  template class StatisticsFile<3>;
} // namespace vefs
