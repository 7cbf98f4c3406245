#include <deal.II/base/mpi_remote_point_evaluation.h>
#include <deal.II/numerics/vector_tools_evaluate.h>

#include <vefs/characteristics.h>

namespace vefs
{
  namespace
  {
    /** Values of all components of the fields at one point. */
    template <int dim>
    using FieldValues =
      Tensor<1, TransportedFields<dim>::max_components, double>;

    /** The fields at @p points through RemotePointEvaluation. */
    template <int dim, int n_components>
    std::vector<FieldValues<dim>>
    evaluate_remotely(const std::vector<Point<dim>> &points,
                      const TransportedFields<dim>  &fields)
    {
      Utilities::MPI::RemotePointEvaluation<dim> evaluation;
      evaluation.reinit(points,
                        fields.dof_handler.get_triangulation(),
                        fields.mapping);
      AssertThrow(evaluation.all_points_found(),
                  ExcMessage("A characteristic foot lies outside the mesh."));
      const auto values =
        VectorTools::point_values<n_components>(evaluation,
                                                fields.dof_handler,
                                                fields.fields);
      std::vector<FieldValues<dim>> result(points.size());
      for (unsigned int k = 0; k < points.size(); ++k)
        for (unsigned int c = 0; c < n_components; ++c)
          result[k][c] = values[k][c];
      return result;
    }

    /**
     * The fields at arbitrary points: in the local part of the mesh (owned
     * and ghost cells) by Q1 interpolation in the cell the locator finds,
     * elsewhere through RemotePointEvaluation on the ranks that own them.
     */
    template <int dim>
    std::vector<FieldValues<dim>>
    evaluate_at(const std::vector<Point<dim>> &points,
                const TransportedFields<dim>  &fields,
                const BoxMeshLocator<dim>     &locator)
    {
      const unsigned int            n_components = fields.n_components;
      std::vector<FieldValues<dim>> values(points.size());
      std::vector<unsigned int>     remote;
      for (unsigned int i = 0; i < points.size(); ++i)
        {
          const auto cell = locator.locate(points[i]);
          if (cell->is_artificial())
            {
              remote.push_back(i);
              continue;
            }
          const Point<dim> xi =
            BoxMeshLocator<dim>::unit_point(cell, points[i]);
          const auto dof_cell = fields.cell_of(cell);
          for (const unsigned int v : cell->vertex_indices())
            {
              const double weight = BoxMeshLocator<dim>::vertex_weight(xi, v);
              for (unsigned int c = 0; c < n_components; ++c)
                values[i][c] +=
                  weight * fields.fields(dof_cell->vertex_dof_index(v, c));
            }
        }

      const auto &triangulation = fields.dof_handler.get_triangulation();
      if (!Utilities::MPI::logical_or(!remote.empty(),
                                      triangulation.get_communicator()))
        return values;

      std::vector<Point<dim>> remote_points;
      for (const unsigned int i : remote)
        remote_points.push_back(points[i]);
      const auto remote_values =
        fields.has_stress()
          ? evaluate_remotely<dim, TransportedFields<dim>::max_components>(
              remote_points,
              fields)
          : evaluate_remotely<dim, dim + 1>(remote_points, fields);
      for (unsigned int k = 0; k < remote.size(); ++k)
        values[remote[k]] = remote_values[k];
      return values;
    }
  } // namespace

  template <int dim>
  void
  advect_along_characteristics(TransportedFields<dim>    &fields,
                               const double               tau,
                               const BoxMeshLocator<dim> &locator)
  {
    const auto &nodes = fields.nodes();

    std::vector<Point<dim>> points(nodes.size());
    for (unsigned int i = 0; i < nodes.size(); ++i)
      points[i] = locator.fold_into_cavity(
        nodes[i].point - 0.5 * tau * fields.velocity(nodes[i]));
    const auto at_midpoints = evaluate_at(points, fields, locator);

    std::vector<double> beyond_contact(nodes.size());
    for (unsigned int i = 0; i < nodes.size(); ++i)
      {
        Tensor<1, dim> u;
        for (unsigned int d = 0; d < dim; ++d)
          u[d] = at_midpoints[i][d];
        const Point<dim> foot = nodes[i].point - tau * u;
        beyond_contact[i]     = locator.distance_beyond_contact_walls(foot);
        points[i]             = locator.fold_into_cavity(foot);
      }
    auto at_feet = evaluate_at(points, fields, locator);
    // Liquid that leaves a contact wall leaves empty space behind: a foot
    // beyond the wall is that far outside the liquid.
    for (unsigned int i = 0; i < nodes.size(); ++i)
      if (beyond_contact[i] > 0)
        at_feet[i][TransportedFields<dim>::level_set_component] =
          std::max(at_feet[i][TransportedFields<dim>::level_set_component],
                   beyond_contact[i]);

    for (unsigned int i = 0; i < nodes.size(); ++i)
      for (unsigned int c = 0; c < fields.n_components; ++c)
        fields.fields(nodes[i].dofs[c]) = at_feet[i][c];
    fields.finalize();
  }

  template void
  advect_along_characteristics<2>(TransportedFields<2> &,
                                  const double,
                                  const BoxMeshLocator<2> &);
  template void
  advect_along_characteristics<3>(TransportedFields<3> &,
                                  const double,
                                  const BoxMeshLocator<3> &);
} // namespace vefs
