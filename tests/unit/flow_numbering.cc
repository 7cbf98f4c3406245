// renumber_flow_dofs() (flow_numbering.h) on the unit square and cube,
// cells of level 2 with those whose centre has x < 0.5 refined to level 3,
// the flow's Q1 velocity and pressure on every cell:
// - 'Flow cells = parents' (grandparents): the interpolated dofs are
//   exactly those at the nodes of cells finer than level 2 (1) that are not
//   nodes of the level-2 (1) lattice (counted by brute force over the
//   vertices' coordinates), (dim + 1) per node; they, and only they, are
//   numbered from n_flow_dofs() on, the velocities in parts 0 and 2 and the
//   pressures in parts 1 and 3 as the cells' elements say; the new numbers
//   are a permutation of 0..n-1 (the owned sets of the ranks partition
//   them). FlowElements::vertex_weights() at each vertex of these cells:
//   the weights sum to 1 and the weighted element vertices are the vertex
//   (Q1 interpolation reproduces linear functions), to round-off.
//   The interpolation and deal.II's hanging-node constraints together give
//   every node of a linear field its value from the unconstrained ones
//   (below 1e-12), on the mesh refined for x < 0.25 only, where 12 (2D)
//   and 224 (3D) unknowns both hang and are interpolated, with
//   grandparents inside the elements.
// - 'Flow cells = finest': no interpolated dofs, and the numbering is
//   deal.II's DoFRenumbering::component_wise() itself, dof by dof.
// Exact integers: 1 and 2 ranks print the same; the nodes off the lattice
// are 30 in 2D and 330 in 3D with parents, 46 and 428 with grandparents.

#include "unit_test.h"

#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_renumbering.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_nothing.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/hp/fe_collection.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_vector.h>

#include <vefs/flow/flow_elements.h>
#include <vefs/flow/flow_numbering.h>
#include <vefs/transport/subtree_partition.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <set>
#include <vector>

using namespace dealii;

namespace
{
  /**
   * The unit square or cube, level 2, the cells with centre x < 0.5
   * refined to level 3; the flow's elements on it as StokesStep's: Q1^(dim
   * + 1), and FE_Nothing (not used here). Partitioned as a simulation with
   * 'Flow cells = grandparents' does: each level-1 cell's descendants on
   * one rank (SubtreePartition).
   */
  template <int dim>
  struct FlowMesh
  {
    /** Refined to level 3 where the cell centre has x < @p refined_below. */
    FlowMesh(const double refined_below = 0.5)
      : triangulation(MPI_COMM_WORLD)
    {
      GridGenerator::hyper_cube(triangulation, 0, 1);
      triangulation.refine_global(2);
      for (const auto &cell : triangulation.active_cell_iterators())
        if (cell->is_locally_owned() && cell->center()[0] < refined_below)
          cell->set_refine_flag();
      triangulation.execute_coarsening_and_refinement();
      vefs::SubtreePartition<dim>(
        1,
        [](const typename Triangulation<dim>::cell_iterator &,
           const typename Triangulation<dim>::CellStatus) { return 1u; })
        .connect_to(triangulation);
      triangulation.repartition();
      triangulation.signals.weight.disconnect_all_slots();
      collection.push_back(FESystem<dim>(FE_Q<dim>(1), dim, FE_Q<dim>(1), 1));
      collection.push_back(
        FESystem<dim>(FE_Nothing<dim>(), dim, FE_Nothing<dim>(), 1));
    }

    /** The flow's dofs on @p dof_handler (of this mesh), renumbered by
     * renumber_flow_dofs() with 'Flow cells = parents' or 'finest'. */
    vefs::FlowNumbering
    number(DoFHandler<dim> &dof_handler, const unsigned int offset) const
    {
      dof_handler.distribute_dofs(collection);
      return vefs::renumber_flow_dofs(dof_handler, elements(offset), 0);
    }

    /** The flow's elements @p offset levels coarser than level 3. */
    static vefs::FlowElements<dim>
    elements(const unsigned int offset)
    {
      vefs::FlowParameters parameters;
      parameters.flow_level_offset = offset;
      return vefs::FlowElements<dim>(parameters, 3);
    }

    parallel::distributed::Triangulation<dim> triangulation;
    hp::FECollection<dim>                     collection;
  };

  /** Whether @p p is a node of the lattice of spacing 1/n. */
  template <int dim>
  bool
  on_lattice(const Point<dim> &p, const double n)
  {
    for (unsigned int d = 0; d < dim; ++d)
      if (std::abs(p[d] * n - std::round(p[d] * n)) > 1e-10)
        return false;
    return true;
  }

  template <int dim>
  void
  check_coarser(std::ostream &out, const unsigned int offset)
  {
    const MPI_Comm            comm = MPI_COMM_WORLD;
    const FlowMesh<dim>       mesh;
    DoFHandler<dim>           dof_handler(mesh.triangulation);
    const vefs::FlowNumbering numbering  = mesh.number(dof_handler, offset);
    const int                 flow_level = 3 - offset;
    const double              n_lattice  = 1 << flow_level;

    // The nodes off the flow level's lattice, from the owned cells: all
    // ranks.
    std::set<std::array<double, dim>> fine_nodes;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && cell->level() > flow_level)
        for (const unsigned int v : cell->vertex_indices())
          if (!on_lattice(cell->vertex(v), n_lattice))
            {
              std::array<double, dim> x;
              for (unsigned int d = 0; d < dim; ++d)
                x[d] = std::round(cell->vertex(v)[d] * 8.);
              fine_nodes.insert(x);
            }
    std::vector<double> coordinates;
    for (const auto &x : fine_nodes)
      coordinates.insert(coordinates.end(), x.begin(), x.end());
    std::set<std::array<double, dim>> all_fine_nodes;
    for (const auto &rank : Utilities::MPI::all_gather(comm, coordinates))
      for (unsigned int i = 0; i < rank.size(); i += dim)
        {
          std::array<double, dim> x;
          std::copy(rank.begin() + i, rank.begin() + i + dim, x.begin());
          all_fine_nodes.insert(x);
        }

    const std::string name =
      std::to_string(dim) +
      (offset == 1 ? "D, parents: " : "D, grandparents: ");
    // Parents: 5 x 9 level-3 nodes in x <= 0.5, 3 x 5 of them on the
    // level-2 lattice; 3D: 5 x 9 x 9 and 3 x 5 x 5. Grandparents: those and
    // the level-2 nodes in x >= 0.5, 45 + 3 x 5 - 5 = 55, 9 of them on the
    // level-1 lattice; 3D: 405 + 3 x 5 x 5 - 5 x 5 = 455 and 27.
    out << name << "nodes off the coarse lattice: " << all_fine_nodes.size()
        << '\n';
    out << name << "interpolated velocities - dim x nodes off the coarse "
        << "lattice: "
        << static_cast<long>(numbering.n_dofs_of_part[2]) -
             static_cast<long>(dim * all_fine_nodes.size())
        << '\n';
    out << name << "interpolated pressures - nodes off the coarse lattice: "
        << static_cast<long>(numbering.n_dofs_of_part[3]) -
             static_cast<long>(all_fine_nodes.size())
        << '\n';
    out << name << "parts add up to the dofs: "
        << (numbering.start(4) == dof_handler.n_dofs() ? "yes" : "NO") << '\n';

    // Each dof of an owned cell in its part: by its node and component.
    unsigned int                         misplaced = 0;
    std::vector<types::global_dof_index> dofs;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const auto &fe = cell->get_fe();
          dofs.resize(fe.n_dofs_per_cell());
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            {
              const auto [component, vertex] = fe.system_to_component_index(i);
              const bool interpolated =
                cell->level() > flow_level &&
                !on_lattice(cell->vertex(vertex), n_lattice);
              const unsigned int part =
                (component < dim ? 0 : 1) + (interpolated ? 2 : 0);
              if (dofs[i] < numbering.start(part) ||
                  dofs[i] >= numbering.start(part + 1))
                ++misplaced;
            }
        }
    out << name
        << "dofs outside their part: " << Utilities::MPI::sum(misplaced, comm)
        << '\n';
    const IndexSet &owned = dof_handler.locally_owned_dofs();
    const bool      partition =
      Utilities::MPI::sum(owned.n_elements(), comm) == dof_handler.n_dofs() &&
      owned.size() == dof_handler.n_dofs();
    out << name << "owned sets partition 0..n-1: "
        << (Utilities::MPI::logical_or(!partition, comm) ? "NO" : "yes")
        << '\n';

    // The weights of the element's vertices at each vertex of its cells.
    const vefs::FlowElements<dim> elements = FlowMesh<dim>::elements(offset);
    double                        weight_error = 0, position_error = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && elements.on_coarser_element(cell))
        for (const unsigned int v : cell->vertex_indices())
          {
            const auto element = elements.element(cell);
            double     sum     = 0;
            Point<dim> x;
            for (const auto &[vertex, weight] :
                 elements.vertex_weights(cell, v))
              {
                sum += weight;
                x += weight * element->vertex(vertex);
              }
            weight_error = std::max(weight_error, std::abs(sum - 1));
            position_error =
              std::max(position_error, x.distance(cell->vertex(v)));
          }
    unit_test::check_below(out,
                           name + "vertex weights: |sum - 1|",
                           Utilities::MPI::max(weight_error, comm),
                           1e-14);
    unit_test::check_below(out,
                           name + "vertex weights: |sum w x - vertex|",
                           Utilities::MPI::max(position_error, comm),
                           1e-14);
  }

  /**
   * The interpolation and deal.II's hanging-node constraints together (as
   * StokesStep makes them) reproduce a linear field, which the elements'
   * Q1 space holds: given at the unknowns that are not constrained, every
   * node gets its value. On a mesh refined to level 3 for x < 0.25 only,
   * so that with grandparents (level-1 elements) nodes hang within an
   * element, between its level-2 and level-3 cells.
   */
  template <int dim>
  void
  check_constraints(std::ostream &out, const unsigned int offset)
  {
    const MPI_Comm      comm = MPI_COMM_WORLD;
    const FlowMesh<dim> mesh(0.25);
    DoFHandler<dim>     dof_handler(mesh.triangulation);
    mesh.number(dof_handler, offset);
    const IndexSet   &owned = dof_handler.locally_owned_dofs();
    const std::string name =
      std::to_string(dim) +
      (offset == 1 ? "D, parents: " : "D, grandparents: ");
    vefs::FlowElements<dim> constrained = FlowMesh<dim>::elements(offset);
    IndexSet                relevant;
    DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
    constrained.exchange_element_dofs(dof_handler, 0, relevant);
    IndexSet touched = relevant;
    touched.add_indices(constrained.far_element_dofs());
    AffineConstraints<double> constraints(touched);
    constrained.make_interpolation_constraints(dof_handler, 0, constraints);
    DoFTools::make_hanging_node_constraints(dof_handler, constraints);
    constraints.close();
    // The nodes that hang and are interpolated: (dim + 1) x 4 in 2D (x =
    // 0.25, y = 1/8, 3/8, 5/8, 7/8), (dim + 1) x 56 in 3D (9 x 9 - 5 x 5).
    const IndexSet interpolated = constrained.interpolated_dofs(dof_handler, 0);
    AffineConstraints<double> hanging(touched);
    DoFTools::make_hanging_node_constraints(dof_handler, hanging);
    unsigned int both = 0;
    for (const auto dof : owned)
      both += interpolated.is_element(dof) && hanging.is_constrained(dof);
    out << name << "unknowns both hanging and interpolated: "
        << Utilities::MPI::sum(both, comm) << '\n';
    const auto linear = [](const Point<dim> &x, const unsigned int c) {
      double value = 1. + c;
      for (unsigned int d = 0; d < dim; ++d)
        value += (d + 2. + c) * x[d];
      return value;
    };
    // Trilinos vectors, as StokesStep's (deal.II 9.4's
    // LinearAlgebra::distributed::Vector hung on 2 ranks building its
    // partitioner for this numbering).
    TrilinosWrappers::MPI::Vector owned_field(owned, comm);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          for (unsigned int c = 0; c <= dim; ++c)
            {
              const auto dof = cell->vertex_dof_index(v, c, 0);
              if (owned.is_element(dof) && !constraints.is_constrained(dof))
                owned_field(dof) = linear(cell->vertex(v), c);
            }
    owned_field.compress(VectorOperation::insert);
    constraints.distribute(owned_field);
    TrilinosWrappers::MPI::Vector field(owned, touched, comm);
    field              = owned_field;
    double field_error = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          for (unsigned int c = 0; c <= dim; ++c)
            field_error =
              std::max(field_error,
                       std::abs(field(cell->vertex_dof_index(v, c, 0)) -
                                linear(cell->vertex(v), c)));
    unit_test::check_below(out,
                           name + "constraints reproduce a linear field",
                           Utilities::MPI::max(field_error, comm),
                           1e-12);
  }

  template <int dim>
  void
  check_finest(std::ostream &out)
  {
    const MPI_Comm            comm = MPI_COMM_WORLD;
    const FlowMesh<dim>       mesh;
    DoFHandler<dim>           renumbered(mesh.triangulation);
    const vefs::FlowNumbering numbering = mesh.number(renumbered, 0);
    DoFHandler<dim>           reference(mesh.triangulation);
    reference.distribute_dofs(mesh.collection);
    std::vector<unsigned int> block_component(dim + 1, 0);
    block_component[dim] = 1;
    DoFRenumbering::component_wise(reference, block_component);

    unsigned int                         different = 0;
    std::vector<types::global_dof_index> a, b;
    auto                                 cell = renumbered.begin_active();
    for (auto other = reference.begin_active(); other != reference.end();
         ++cell, ++other)
      if (cell->is_locally_owned())
        {
          a.resize(cell->get_fe().n_dofs_per_cell());
          b.resize(a.size());
          cell->get_dof_indices(a);
          other->get_dof_indices(b);
          different += (a != b);
        }
    const std::string name = std::to_string(dim) + "D, finest: ";
    out << name << "interpolated dofs: "
        << numbering.n_dofs_of_part[2] + numbering.n_dofs_of_part[3] << '\n';
    out << name << "cells numbered unlike component_wise(): "
        << Utilities::MPI::sum(different, comm) << '\n';
  }
} // namespace

int
main(int argc, char **argv)
{
  return unit_test::run(argc, argv, [](std::ostream &out) {
    check_coarser<2>(out, 1);
    check_coarser<3>(out, 1);
    check_coarser<2>(out, 2);
    check_coarser<3>(out, 2);
    for (const unsigned int offset : {1u, 2u})
      {
        check_constraints<2>(out, offset);
        check_constraints<3>(out, offset);
      }
    check_finest<2>(out);
    check_finest<3>(out);
  });
}
