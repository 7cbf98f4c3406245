// VertexFieldTransfer (vertex_field_transfer.h) against deal.II's
// parallel::distributed::SolutionTransfer through one mesh change that
// refines some cells and coarsens others, on a mesh with hanging nodes,
// 2D and 3D, 1 and 2 ranks. Carried: every component of the fields (with
// stress) and the dim gradient slots of a second vector. Both
// interpolate Q1 onto children and take the parent's values at its
// children's corners, so the owned entries must agree after the
// constraints are distributed, up to the order of the sums (relative
// difference below 1e-14; seen: 0).
// Then the same with a LatticeSource that packs, for the cells to be
// refined, the parent's Q1 interpolant at the lattice of its children's
// vertices (all carried components: the children take these values
// instead of the transfer's own interpolation, so a lattice written to the
// wrong places shows), and for the cells to be coarsened their children's
// values, handed back once per coarsened family.

#include "unit_test.h"

#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/distributed/solution_transfer.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/grid/grid_generator.h>

#include <vefs/compat/box_mesh_locator.h>
#include <vefs/fields/vertex_field_transfer.h>

#include <iostream>

using namespace dealii;

namespace
{
  /** Q1 values at the lattice points; the children's values when coarsened. */
  template <int dim>
  class Q1Lattice : public vefs::VertexFieldTransfer<dim>::LatticeSource
  {
  public:
    using VectorType = typename vefs::TransportedFields<dim>::VectorType;

    Q1Lattice(const vefs::TransportedFields<dim> &fields,
              const VectorType                   &second)
      : fields(fields)
      , second(second)
    {
      for (unsigned int c = 0; c < fields.n_components; ++c)
        carried.emplace_back(0, c);
      for (unsigned int d = 0; d < dim; ++d)
        carried.emplace_back(1, d);
    }

    std::vector<std::pair<unsigned int, unsigned int>>
    components() const override
    {
      return carried;
    }

    std::vector<double>
    pack(const typename Triangulation<dim>::cell_iterator &cell,
         const typename Triangulation<dim>::CellStatus status) const override
    {
      constexpr unsigned int n_points = vefs::FamilyLattice<dim>::n_points;
      std::vector<double>    lattice(n_points * carried.size());
      if (status == Triangulation<dim>::CELL_REFINE)
        {
          const auto dof_cell = fields.cell_of(cell);
          for (unsigned int i = 0; i < n_points; ++i)
            for (const unsigned int v : dof_cell->vertex_indices())
              {
                const double weight = vefs::BoxMeshLocator<dim>::vertex_weight(
                  vefs::FamilyLattice<dim>::unit_point(i),
                  v);
                for (unsigned int k = 0; k < carried.size(); ++k)
                  lattice[i * carried.size() + k] +=
                    weight * value(dof_cell, v, k);
              }
          return lattice;
        }
      if (status == Triangulation<dim>::CELL_COARSEN)
        {
          for (unsigned int child = 0; child < cell->n_children(); ++child)
            {
              const auto fine = fields.cell_of(cell->child(child));
              for (const unsigned int v : fine->vertex_indices())
                for (unsigned int k = 0; k < carried.size(); ++k)
                  lattice[vefs::FamilyLattice<dim>::point(child, v) *
                            carried.size() +
                          k] = value(fine, v, k);
            }
          return lattice;
        }
      return {};
    }

    void
    keep(const typename Triangulation<dim>::active_cell_iterator &,
         const double *) override
    {
      ++n_kept;
    }

    unsigned int n_kept = 0;

  private:
    template <typename CellIterator>
    double
    value(const CellIterator &cell,
          const unsigned int  v,
          const unsigned int  k) const
    {
      const auto [slot, component] = carried[k];
      return (slot == 0 ? fields.vector()
                        : second)(cell->vertex_dof_index(v, component));
    }

    const vefs::TransportedFields<dim>                &fields;
    const VectorType                                  &second;
    std::vector<std::pair<unsigned int, unsigned int>> carried;
  };

  template <int dim>
  void
  check(std::ostream &out, const bool with_lattice)
  {
    using VectorType = typename vefs::TransportedFields<dim>::VectorType;
    const MPI_Comm                            comm = MPI_COMM_WORLD;
    parallel::distributed::Triangulation<dim> triangulation(comm);
    GridGenerator::hyper_cube(triangulation, -1, 1, true);
    triangulation.refine_global(dim == 2 ? 3 : 2);
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned() && cell->center()[0] > 0)
        cell->set_refine_flag();
    triangulation.execute_coarsening_and_refinement();

    vefs::TransportedFields<dim> fields(triangulation, true, false, {});
    fields.setup_dofs();
    const unsigned int n_stress =
      vefs::TransportedFields<dim>::n_stress_components;
    fields.interpolate(
      unit_test::Smooth<dim>(1, 0.5),
      unit_test::Smooth<dim>(dim, -0.3),
      std::make_unique<unit_test::Smooth<dim>>(n_stress, 2.).get());
    // The gradient slots hold something else than a gradient here: any
    // values do.
    VectorType gradient;
    fields.initialize_vector(gradient);
    for (const auto &node : fields.nodes())
      for (unsigned int d = 0; d < dim; ++d)
        gradient(node.dofs[d]) =
          std::cos(3 * node.point[d] + d) * (1 + node.point[0]);
    fields.make_consistent(gradient);

    // Refine the fine cells at y > 0.2, coarsen those at y < -0.2 (p4est
    // coarsens whole families only), refine once more at the coarse cells
    // near x = -0.5.
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const Point<dim> c = cell->center();
          if (c[0] > 0 && c[1] > 0.2)
            cell->set_refine_flag();
          else if (c[0] > 0 && c[1] < -0.2)
            cell->set_coarsen_flag();
          else if (std::abs(c[0] + 0.5) < 0.2)
            cell->set_refine_flag();
        }
    triangulation.prepare_coarsening_and_refinement();
    unsigned int n_refined = 0, n_coarsened = 0;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          n_refined += cell->refine_flag_set() ? 1 : 0;
          n_coarsened += cell->coarsen_flag_set() ? 1 : 0;
        }

    std::vector<unsigned int> all_components, gradient_components;
    for (unsigned int c = 0; c < fields.n_components; ++c)
      all_components.push_back(c);
    for (unsigned int d = 0; d < dim; ++d)
      gradient_components.push_back(d);
    Q1Lattice<dim>                 lattice(fields, gradient);
    vefs::VertexFieldTransfer<dim> transfer(triangulation,
                                            fields,
                                            {{&fields.vector(), all_components},
                                             {&gradient, gradient_components}},
                                            with_lattice ? &lattice : nullptr);
    parallel::distributed::SolutionTransfer<dim, VectorType> reference(
      fields.dof_handler);
    reference.prepare_for_coarsening_and_refinement(
      std::vector<const VectorType *>{&fields.vector(), &gradient});
    triangulation.execute_coarsening_and_refinement();

    fields.setup_dofs();
    VectorType mine_fields, mine_gradient, their_fields, their_gradient;
    for (VectorType *vector :
         {&mine_fields, &mine_gradient, &their_fields, &their_gradient})
      {
        fields.initialize_vector(*vector);
        vector->zero_out_ghost_values();
      }
    transfer.unpack(fields, {&mine_fields, &mine_gradient});
    std::vector<VectorType *> theirs{&their_fields, &their_gradient};
    reference.interpolate(theirs);
    for (VectorType *vector :
         {&mine_fields, &mine_gradient, &their_fields, &their_gradient})
      {
        vector->update_ghost_values();
        fields.distribute_constraints(*vector);
      }

    // Relative to the largest entry.
    double difference = 0, largest = 0;
    for (const auto index : fields.owned_dofs)
      {
        largest = std::max(largest, std::abs(their_fields(index)));
        difference =
          std::max(difference,
                   std::abs(mine_fields(index) - their_fields(index)));
      }
    for (const auto &node : fields.nodes())
      for (unsigned int d = 0; d < dim; ++d)
        difference = std::max(difference,
                              std::abs(mine_gradient(node.dofs[d]) -
                                       their_gradient(node.dofs[d])));

    const std::string name =
      std::to_string(dim) + "D, " + (with_lattice ? "Q1 lattice, " : "");
    out << name << "cells refined: " << Utilities::MPI::sum(n_refined, comm)
        << ", coarsened: " << Utilities::MPI::sum(n_coarsened, comm)
        << ", cells after: " << triangulation.n_global_active_cells() << '\n';
    unit_test::check_below(out,
                           name + "difference from SolutionTransfer, relative",
                           Utilities::MPI::max(difference, comm) /
                             Utilities::MPI::max(largest, comm),
                           1e-14);
    if (with_lattice)
      out << name << "lattices handed back: "
          << Utilities::MPI::sum(lattice.n_kept, comm) << " (coarsened / "
          << GeometryInfo<dim>::max_children_per_cell << " = "
          << Utilities::MPI::sum(n_coarsened, comm) /
               GeometryInfo<dim>::max_children_per_cell
          << ")\n";
  }
} // namespace

int
main(int argc, char **argv)
{
  return unit_test::run(argc, argv, [](std::ostream &out) {
    for (const bool with_lattice : {false, true})
      {
        check<2>(out, with_lattice);
        check<3>(out, with_lattice);
      }
  });
}
