#include <deal.II/base/mpi_remote_point_evaluation.h>

#include <deal.II/numerics/vector_tools_evaluate.h>

#include <vefs/characteristics.h>

namespace vefs
{
  namespace
  {
    /** Keep a point inside the cavity, a hair away from its walls. */
    template <int dim>
    Point<dim>
    clamp_to(const BoundingBox<dim> &box, const Point<dim> &p)
    {
      Point<dim> q;
      for (unsigned int d = 0; d < dim; ++d)
        {
          const double margin = 1e-10 * box.side_length(d);
          q[d]                = std::min(std::max(p[d], box.lower_bound(d) + margin),
                          box.upper_bound(d) - margin);
        }
      return q;
    }

    template <int dim>
    std::vector<Tensor<1, dim + 1>>
    evaluate_at(const std::vector<Point<dim>> &points,
                const TransportedFields<dim> & fields)
    {
      Utilities::MPI::RemotePointEvaluation<dim> evaluation;
      evaluation.reinit(points,
                        fields.dof_handler.get_triangulation(),
                        fields.mapping);
      AssertThrow(evaluation.all_points_found(),
                  ExcMessage("A characteristic foot lies outside the mesh."));
      return VectorTools::point_values<dim + 1>(evaluation,
                                                fields.dof_handler,
                                                fields.fields);
    }
  } // namespace

  template <int dim>
  void
  advect_along_characteristics(TransportedFields<dim> &fields,
                               const double            tau,
                               const BoundingBox<dim> &cavity)
  {
    const auto &nodes = fields.nodes();

    std::vector<Point<dim>> points(nodes.size());
    for (unsigned int i = 0; i < nodes.size(); ++i)
      {
        Tensor<1, dim> u;
        for (unsigned int d = 0; d < dim; ++d)
          u[d] = fields.fields(nodes[i].dofs[d]);
        points[i] = clamp_to(cavity, nodes[i].point - 0.5 * tau * u);
      }
    const auto at_midpoints = evaluate_at(points, fields);

    for (unsigned int i = 0; i < nodes.size(); ++i)
      {
        Tensor<1, dim> u;
        for (unsigned int d = 0; d < dim; ++d)
          u[d] = at_midpoints[i][d];
        points[i] = clamp_to(cavity, nodes[i].point - tau * u);
      }
    const auto at_feet = evaluate_at(points, fields);

    for (unsigned int i = 0; i < nodes.size(); ++i)
      for (unsigned int c = 0; c < dim + 1; ++c)
        fields.fields(nodes[i].dofs[c]) = at_feet[i][c];
    fields.finalize();
  }

  template void
  advect_along_characteristics<2>(TransportedFields<2> &,
                                  const double,
                                  const BoundingBox<2> &);
  template void
  advect_along_characteristics<3>(TransportedFields<3> &,
                                  const double,
                                  const BoundingBox<3> &);
} // namespace vefs
