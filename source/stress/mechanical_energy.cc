#include <deal.II/base/mpi.h>

#include <vefs/stress/mechanical_energy.h>

namespace vefs
{
  template <int dim>
  MechanicalEnergy
  mechanical_energy(const TransportedFields<dim> &fields,
                    const LiquidDomain<dim>      &domain,
                    const MaterialParameters     &material,
                    const Rheology<dim>          &rheology)
  {
    Tensor<1, dim> gravity;
    for (unsigned int d = 0; d < dim; ++d)
      gravity[d] = material.gravity[d];
    const bool has_stress = rheology.has_stress();

    LiquidValues<dim> liquid_values(domain);
    std::array<Tensor<1, dim>, GeometryInfo<dim>::vertices_per_cell> vertex_u;
    std::array<SymmetricTensor<2, dim>, GeometryInfo<dim>::vertices_per_cell>
                     vertex_sigma;
    MechanicalEnergy energy;
    for (const auto &cell : fields.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && domain.has_liquid(cell))
        {
          for (const unsigned int v : cell->vertex_indices())
            {
              vertex_u[v] = fields.velocity_at(cell, v);
              if (has_stress)
                vertex_sigma[v] = fields.stress_at(cell, v);
            }
          const BoxCellValues<dim> &values = liquid_values.reinit(cell);
          for (unsigned int q = 0; q < values.size(); ++q)
            {
              const Tensor<1, dim> u = values.value(vertex_u, q);
              energy.kinetic +=
                kinetic_energy_density(material.density, u) * values.JxW[q];
              energy.potential += potential_energy_density(material.density,
                                                           gravity,
                                                           values.point[q]) *
                                  values.JxW[q];
              if (has_stress)
                energy.elastic += rheology.elastic_energy_density(
                                    values.value(vertex_sigma, q)) *
                                  values.JxW[q];
            }
        }
    const MPI_Comm comm =
      fields.dof_handler.get_triangulation().get_communicator();
    energy.kinetic   = Utilities::MPI::sum(energy.kinetic, comm);
    energy.potential = Utilities::MPI::sum(energy.potential, comm);
    energy.elastic   = Utilities::MPI::sum(energy.elastic, comm);
    return energy;
  }

  template MechanicalEnergy
  mechanical_energy<2>(const TransportedFields<2> &,
                       const LiquidDomain<2> &,
                       const MaterialParameters &,
                       const Rheology<2> &);
  template MechanicalEnergy
  mechanical_energy<3>(const TransportedFields<3> &,
                       const LiquidDomain<3> &,
                       const MaterialParameters &,
                       const Rheology<3> &);
} // namespace vefs
