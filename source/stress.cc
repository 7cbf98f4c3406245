#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <vefs/free_surface.h>
#include <vefs/stress.h>

namespace vefs
{
  namespace
  {
    /**
     * Smallest eigenvalue of a symmetric tensor, real even when the tensor
     * is close to a multiple of the identity (the closed form of
     * eigenvalues() then takes the root of a slightly negative number).
     */
    double
    smallest_eigenvalue(const SymmetricTensor<2, 2> &c)
    {
      const double mean = 0.5 * (c[0][0] + c[1][1]);
      const double half = 0.5 * (c[0][0] - c[1][1]);
      return mean - std::sqrt(half * half + c[0][1] * c[0][1]);
    }

    double
    smallest_eigenvalue(const SymmetricTensor<2, 3> &c)
    {
      // Jacobi rotations: robust for clustered eigenvalues; sorted in
      // descending order.
      return eigenvectors(c, SymmetricTensorEigenvectorMethod::jacobi)[2].first;
    }
  } // namespace

  template <int dim>
  StressUpdateReport
  update_stress(TransportedFields<dim>  &fields,
                const LiquidDomain<dim> &domain,
                const Rheology<dim>     &rheology,
                const double             tau)
  {
    using VectorType = typename TransportedFields<dim>::VectorType;
    constexpr unsigned int first =
      TransportedFields<dim>::first_stress_component;
    constexpr unsigned int n_stress =
      TransportedFields<dim>::n_stress_components;

    // Sum over the liquid cells around each node of volume * new stress;
    // the volume itself goes into the node's first component.
    VectorType sum;
    fields.initialize_vector(sum);
    // Quadrature points at the vertices, in the vertex order of the cell.
    FEValues<dim>                    vertex_values(fields.mapping,
                                fields.fe,
                                QTrapezoid<dim>(),
                                update_gradients);
    const FEValuesExtractors::Vector velocity(0);
    std::vector<Tensor<2, dim>> grad_u(GeometryInfo<dim>::vertices_per_cell);
    StressUpdateReport          report;
    for (const auto &cell : fields.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && domain.has_liquid(cell))
        {
          vertex_values.reinit(cell);
          vertex_values[velocity].get_function_gradients(fields.fields, grad_u);
          const double weight = cell->measure();
          for (const unsigned int v : cell->vertex_indices())
            {
              SymmetricTensor<2, dim> advected;
              for (unsigned int i = 0; i < n_stress; ++i)
                advected.access_raw_entry(i) =
                  fields.fields(cell->vertex_dof_index(v, first + i));
              const SymmetricTensor<2, dim> updated =
                rheology.updated_stress(advected, grad_u[v], tau);
              report.max_velocity_gradient =
                std::max(report.max_velocity_gradient, grad_u[v].norm());
              if (rheology.is_strain_limited(grad_u[v], tau))
                ++report.strain_limited_points;
              sum(cell->vertex_dof_index(v, 0)) += weight;
              for (unsigned int i = 0; i < n_stress; ++i)
                sum(cell->vertex_dof_index(v, first + i)) +=
                  weight * updated.access_raw_entry(i);
            }
        }
    sum.compress(VectorOperation::add);

    for (const auto &node : fields.nodes())
      {
        const double weight = sum(node.dofs[0]);
        if (weight > 0)
          for (unsigned int i = 0; i < n_stress; ++i)
            fields.fields(node.dofs[first + i]) =
              sum(node.dofs[first + i]) / weight;
      }
    fields.finalize();

    const MPI_Comm comm =
      fields.dof_handler.get_triangulation().get_communicator();
    report.max_velocity_gradient =
      Utilities::MPI::max(report.max_velocity_gradient, comm);
    report.strain_limited_points =
      Utilities::MPI::sum(report.strain_limited_points, comm);
    return report;
  }

  template <int dim>
  StressMeasure
  measure_stress(const TransportedFields<dim> &fields,
                 const LiquidDomain<dim>      &domain,
                 const Rheology<dim>          &rheology)
  {
    LiquidValues<dim> liquid_values(domain);
    std::array<SymmetricTensor<2, dim>, GeometryInfo<dim>::vertices_per_cell>
      vertex_sigma;

    StressMeasure measure;
    for (const auto &cell : fields.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && domain.has_liquid(cell))
        {
          for (const unsigned int v : cell->vertex_indices())
            for (unsigned int c = 0;
                 c < TransportedFields<dim>::n_stress_components;
                 ++c)
              vertex_sigma
                [v][SymmetricTensor<2, dim>::unrolled_to_component_indices(c)] =
                  fields.fields(cell->vertex_dof_index(
                    v,
                    TransportedFields<dim>::first_stress_component + c));
          const BoxCellValues<dim> &values = liquid_values.reinit(cell);
          for (unsigned int q = 0; q < values.size(); ++q)
            {
              const SymmetricTensor<2, dim> sigma =
                values.value(vertex_sigma, q);
              measure.elastic_energy +=
                rheology.elastic_energy_density(sigma) * values.JxW[q];
              const double lowest =
                smallest_eigenvalue(rheology.conformation(sigma));
              measure.min_conformation_eigenvalue =
                std::min(measure.min_conformation_eigenvalue, lowest);
              if (!(lowest > 0))
                ++measure.non_positive_points;
            }
        }
    const MPI_Comm comm =
      fields.dof_handler.get_triangulation().get_communicator();
    measure.elastic_energy = Utilities::MPI::sum(measure.elastic_energy, comm);
    measure.min_conformation_eigenvalue =
      Utilities::MPI::min(measure.min_conformation_eigenvalue, comm);
    measure.non_positive_points =
      Utilities::MPI::sum(measure.non_positive_points, comm);
    return measure;
  }

  template StressUpdateReport
  update_stress<2>(TransportedFields<2> &,
                   const LiquidDomain<2> &,
                   const Rheology<2> &,
                   const double);
  template StressUpdateReport
  update_stress<3>(TransportedFields<3> &,
                   const LiquidDomain<3> &,
                   const Rheology<3> &,
                   const double);
  template StressMeasure
  measure_stress<2>(const TransportedFields<2> &,
                    const LiquidDomain<2> &,
                    const Rheology<2> &);
  template StressMeasure
  measure_stress<3>(const TransportedFields<3> &,
                    const LiquidDomain<3> &,
                    const Rheology<3> &);
} // namespace vefs
