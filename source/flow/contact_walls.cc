#include <deal.II/base/mpi.h>

#include <Epetra_CrsMatrix.h>
#include <vefs/compat/mpi_concatenate.h>
#include <vefs/flow/contact_walls.h>

#include <algorithm>
#include <array>
#include <set>

namespace vefs
{
  namespace
  {
    /** A node's coordinates, exact: the same vertex in every mesh. */
    template <int dim>
    std::array<double, dim>
    coordinates(const Point<dim> &p)
    {
      std::array<double, dim> x;
      for (unsigned int d = 0; d < dim; ++d)
        x[d] = p[d];
      return x;
    }

    /**
     * The global columns and values of the owned @p row. (Through Epetra:
     * deal.II's row iterators look for the next non-empty row through all
     * rows of the matrix, which cost 0.3 s a step on the 3D ball.)
     */
    void
    copy_row(const TrilinosWrappers::SparseMatrix &matrix,
             const types::global_dof_index         row,
             std::vector<types::global_dof_index> &columns,
             std::vector<double>                  &values)
    {
      const Epetra_CrsMatrix &epetra    = matrix.trilinos_matrix();
      const int               local_row = epetra.RowMap().LID(
        static_cast<TrilinosWrappers::types::int_type>(row));
      Assert(local_row >= 0, ExcInternalError());
      int     n_entries;
      double *row_values;
      int    *local_columns;
      epetra.ExtractMyRowView(local_row, n_entries, row_values, local_columns);
      columns.resize(n_entries);
      values.assign(row_values, row_values + n_entries);
      for (int k = 0; k < n_entries; ++k)
        columns[k] = epetra.ColMap().GID64(local_columns[k]);
    }
  } // namespace

  template <int dim>
  ContactWalls<dim>::ContactWalls(const CavityParameters &parameters)
  {
    for (unsigned int w = 0; w < 2 * dim; ++w)
      if (parameters.wall_type[w] == WallType::contact)
        walls.push_back(w);
  }

  template <int dim>
  bool
  ContactWalls<dim>::is_on_contact_wall(
    const typename Triangulation<dim>::cell_iterator &cell,
    const unsigned int                                face) const
  {
    return cell->at_boundary(face) &&
           std::find(walls.begin(),
                     walls.end(),
                     cell->face(face)->boundary_id()) != walls.end();
  }

  template <int dim>
  void
  ContactWalls<dim>::reset(const DoFHandler<dim>           &dof_handler,
                           const IndexSet                  &owned,
                           const IndexSet                  &relevant,
                           const IndexSet                  &touched,
                           const unsigned int               liquid_index,
                           const AffineConstraints<double> &interpolation)
  {
    const MPI_Comm comm = dof_handler.get_triangulation().get_communicator();
    wall_unknowns.clear();
    any_wall_unknowns = false;
    in_contact.reinit(owned, relevant, comm);
    reactions.reinit(owned, comm);
    this->touched = touched;
    if (walls.empty())
      return;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (!cell->is_artificial() && cell->active_fe_index() == liquid_index &&
          cell->at_boundary())
        for (const unsigned int f : cell->face_indices())
          if (is_on_contact_wall(cell, f))
            {
              const types::boundary_id wall = cell->face(f)->boundary_id();
              // Q1 in every component: the dofs of a face sit at its
              // vertices, the velocity component c being the c-th of each.
              for (const unsigned int v : cell->face(f)->vertex_indices())
                {
                  const types::global_dof_index dof =
                    cell->face(f)->vertex_dof_index(v, wall / 2, liquid_index);
                  if (!interpolation.is_constrained(dof))
                    wall_unknowns[dof] = {wall % 2 == 0 ? -1 : 1,
                                          cell->face(f)->vertex(v)};
                }
            }
    any_wall_unknowns =
      Utilities::MPI::logical_or(!wall_unknowns.empty(), comm);

    // Where the last step ended released (from every rank: the partition
    // has changed since), the liquid is likely to leave the wall again.
    std::set<std::array<double, dim>> released;
    for (const Point<dim> &p : concatenated_over_ranks(comm, released_nodes))
      released.insert(coordinates(p));
    for (const auto &entry : wall_unknowns)
      if (owned.is_element(entry.first))
        in_contact(entry.first) =
          released.count(coordinates(entry.second.node)) > 0 ? 0 : 1;
    in_contact.update_ghost_values();
  }

  template <int dim>
  double
  ContactWalls<dim>::power(
    const std::function<double(types::global_dof_index)> &velocity) const
  {
    double power = 0;
    for (const auto &[dof, unknown] : wall_unknowns)
      if (reactions.locally_owned_elements().is_element(dof))
        power += reactions(dof) * velocity(dof);
    return Utilities::MPI::sum(power, in_contact.get_mpi_communicator());
  }

  template <int dim>
  std::vector<Point<dim>>
  ContactWalls<dim>::saved_state() const
  {
    if (walls.empty())
      return {};
    return concatenated_over_ranks(in_contact.get_mpi_communicator(),
                                   released_nodes);
  }

  template <int dim>
  void
  ContactWalls<dim>::resume(const std::vector<Point<dim>> &released)
  {
    released_nodes = released;
  }

  template <int dim>
  void
  ContactWalls<dim>::set_zero(BlockVector &vector) const
  {
    for (const auto &[row, kept] : kept_rows)
      if (kept.imposed)
        vector.block(0)(row) = 0;
    vector.compress(VectorOperation::insert);
  }

  template <int dim>
  void
  ContactWalls<dim>::keep_rows(
    TrilinosWrappers::BlockSparseMatrix &matrix,
    BlockVector                         &rhs,
    const AffineConstraints<double>     &other_constraints)
  {
    kept_rows.clear();
    const IndexSet &owned = in_contact.locally_owned_elements();
    for (const auto &entry : wall_unknowns)
      if (owned.is_element(entry.first) &&
          !other_constraints.is_constrained(entry.first))
        {
          const types::global_dof_index row  = entry.first;
          KeptRow                      &kept = kept_rows[row];
          copy_row(matrix.block(0, 0),
                   row,
                   kept.velocity_columns,
                   kept.velocity_values);
          copy_row(matrix.block(0, 1),
                   row,
                   kept.pressure_columns,
                   kept.pressure_values);
          kept.diagonal = matrix.block(0, 0).diag_element(row);
          kept.rhs      = rhs.block(0)(row);
          kept.imposed  = false;
        }
    impose(matrix, rhs);
  }

  template <int dim>
  void
  ContactWalls<dim>::impose(TrilinosWrappers::BlockSparseMatrix &matrix,
                            BlockVector                         &rhs)
  {
    for (auto &[row, kept] : kept_rows)
      {
        const bool imposed = in_contact(row) == 1;
        if (imposed == kept.imposed)
          continue;
        if (imposed)
          {
            matrix.block(0, 0).clear_row(row, kept.diagonal);
            matrix.block(0, 1).clear_row(row);
            rhs.block(0)(row) = 0;
          }
        else
          {
            matrix.block(0, 0).set(row,
                                   kept.velocity_columns,
                                   kept.velocity_values);
            matrix.block(0, 1).set(row,
                                   kept.pressure_columns,
                                   kept.pressure_values);
            rhs.block(0)(row) = kept.rhs;
          }
        kept.imposed = imposed;
      }
    matrix.compress(VectorOperation::insert);
    rhs.compress(VectorOperation::insert);
  }

  template <int dim>
  bool
  ContactWalls<dim>::update(const DoFHandler<dim>           &dof_handler,
                            const LiquidDomain<dim>         &domain,
                            const BlockVector               &solution,
                            StokesCellSystem<dim>           &local,
                            GhostPenalty<dim>               &ghost_penalty,
                            const FlowElements<dim>         &elements,
                            const AffineConstraints<double> &interpolation)
  {
    const MPI_Comm comm = dof_handler.get_triangulation().get_communicator();
    // The reaction of a constrained degree of freedom is its residual in
    // the equations without the constraint: int (S n) . phi_i over the
    // wall, the force the wall puts on the liquid there.
    // Summed on the unknowns' owners: a cell's or face's unknowns may be
    // interpolated from ones that only the owner knows to be at a wall.
    Vector reaction(in_contact.locally_owned_elements(), touched, comm);
    const types::global_dof_index n_velocities = in_contact.size();
    // A residual in the flow space's own velocity unknowns (FlowNumbering:
    // they come first, the interpolated ones after the pressures).
    const auto add_to_velocity = [&](const types::global_dof_index dof,
                                     const double                  residual) {
      if (dof < n_velocities)
        reaction(dof) += residual;
    };
    const auto add_reaction = [&](const types::global_dof_index dof,
                                  const double                  residual) {
      if (const auto *entries = interpolation.get_constraint_entries(dof))
        {
          for (const auto &[from, weight] : *entries)
            add_to_velocity(from, weight * residual);
        }
      else
        add_to_velocity(dof, residual);
    };
    std::vector<types::global_dof_index> dofs;
    dealii::Vector<double>               values, residual;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && domain.has_liquid(cell) &&
          elements.element(cell)->at_boundary())
        {
          const auto element         = elements.element(cell);
          bool       on_contact_wall = false;
          for (const unsigned int f : element->face_indices())
            if (is_on_contact_wall(element, f))
              on_contact_wall = true;
          if (!on_contact_wall)
            continue;
          local.compute(cell);
          dofs.resize(cell->get_fe().n_dofs_per_cell());
          cell->get_dof_indices(dofs);
          values.reinit(dofs.size());
          residual.reinit(dofs.size());
          for (unsigned int i = 0; i < dofs.size(); ++i)
            values(i) = solution(dofs[i]);
          local.matrix.vmult(residual, values);
          residual -= local.rhs;
          for (unsigned int i = 0; i < dofs.size(); ++i)
            add_reaction(dofs[i], residual(i));
        }
    // Only faces next to a wall can hold wall unknowns.
    ghost_penalty.for_each_face(
      dof_handler,
      true,
      [&](const FullMatrix<double> &matrix,
          const FullMatrix<double> &,
          const std::vector<types::global_dof_index> &face_dofs) {
        // Read once: an access by global index searches the vector's map.
        values.reinit(face_dofs.size());
        residual.reinit(face_dofs.size());
        for (unsigned int j = 0; j < face_dofs.size(); ++j)
          values(j) = solution(face_dofs[j]);
        matrix.vmult(residual, values);
        for (unsigned int i = 0; i < face_dofs.size(); ++i)
          add_reaction(face_dofs[i], residual(i));
      },
      GhostPenalty<dim>::Faces::next_to_walls);
    reaction.compress(VectorOperation::add);

    bool changed = false;
    force        = 0;
    for (const auto &[dof, unknown] : wall_unknowns)
      if (in_contact.locally_owned_elements().is_element(dof))
        {
          // The reactions the solution felt, though an unknown may be
          // released now; a free unknown has none.
          reactions(dof) = in_contact(dof) == 1 ? reaction(dof) : 0.;
          if (in_contact(dof) == 1)
            {
              force -= unknown.sign * reaction(dof);
              // A wall pushes; one that would pull lets the liquid go.
              if (unknown.sign * reaction(dof) > 0)
                {
                  in_contact(dof) = 0;
                  changed         = true;
                }
            }
          else if (unknown.sign * solution(dof) > 0)
            {
              // Released, but the liquid would cross the wall there.
              in_contact(dof) = 1;
              changed         = true;
            }
        }
    in_contact.update_ghost_values();
    force = Utilities::MPI::sum(force, comm);

    released_nodes.clear();
    for (const auto &entry : wall_unknowns)
      if (in_contact.locally_owned_elements().is_element(entry.first) &&
          in_contact(entry.first) == 0)
        released_nodes.push_back(entry.second.node);

    // Wall faces of liquid cells all of whose normal unknowns are in
    // contact.
    contact_measure = 0;
    std::vector<types::global_dof_index> face_dofs;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && cell->at_boundary() &&
          domain.has_liquid(cell))
        for (const unsigned int f : cell->face_indices())
          if (is_on_contact_wall(cell, f))
            {
              face_dofs.resize(cell->get_fe().n_dofs_per_face());
              cell->face(f)->get_dof_indices(face_dofs,
                                             cell->active_fe_index());
              bool touching = true;
              for (const auto dof : face_dofs)
                if (wall_unknowns.count(dof) > 0 && in_contact(dof) != 1)
                  touching = false;
              if (touching)
                contact_measure += cell->face(f)->measure();
            }
    contact_measure = Utilities::MPI::sum(contact_measure, comm);
    return Utilities::MPI::logical_or(changed, comm);
  }

  template class ContactWalls<2>;
  template class ContactWalls<3>;
} // namespace vefs
