#include <deal.II/base/qprojector.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_renumbering.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_nothing.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/hp/fe_values.h>
#include <deal.II/lac/block_sparsity_pattern.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/numerics/vector_tools_boundary.h>

#include <Epetra_CrsGraph.h>
#include <Epetra_CrsMatrix.h>
#include <Epetra_Map.h>
#include <Epetra_MultiVector.h>
#include <Teuchos_ParameterList.hpp>
#include <vefs/compat/box_q1_values.h>
#include <vefs/compat/owned_rows_matrix.h>
#include <vefs/flow/flow_numbering.h>
#include <vefs/flow/ghost_penalty.h>
#include <vefs/flow/stokes_cell_system.h>
#include <vefs/flow/stokes_step.h>
#include <vefs/transport/free_surface.h>
#include <vefs/transport/initial_liquid.h>

#include <iomanip>
#include <map>
#include <sstream>

namespace vefs
{
  namespace
  {
    /** A wall velocity as a function of velocity and pressure components. */
    template <int dim>
    class FlowBoundaryValues : public Function<dim>
    {
    public:
      explicit FlowBoundaryValues(const Function<dim> &velocity)
        : Function<dim>(dim + 1)
        , velocity(velocity)
      {
      }

      double
      value(const Point<dim> &p, const unsigned int component) const override
      {
        return component < dim ? velocity.value(p, component) : 0.;
      }

    private:
      const Function<dim> &velocity;
    };

    /**
     * Block-triangular preconditioner of [A B^T; B -C]: one AMG V-cycle for
     * A and the Cahouet-Chabard approximation of the Schur complement,
     * S^-1 ~ mu M_p^-1 + L_w^-1, with L_w the pressure Laplacian weighted by
     * tau/rho + tau_K (lumped mass; one AMG V-cycle for L_w). It covers the
     * mass-dominated and the viscous-dominated ends alike.
     */
    class BlockPreconditioner
    {
    public:
      BlockPreconditioner(
        const TrilinosWrappers::BlockSparseMatrix &system,
        const TrilinosWrappers::PreconditionAMG   &velocity_amg,
        const TrilinosWrappers::PreconditionAMG   &laplace_amg,
        const TrilinosWrappers::MPI::Vector       &scaled_inverse_mass)
        : system(system)
        , velocity_amg(velocity_amg)
        , laplace_amg(laplace_amg)
        , scaled_inverse_mass(scaled_inverse_mass)
        , tmp(system.block(0, 0).locally_owned_range_indices(),
              scaled_inverse_mass.get_mpi_communicator())
      {
      }

      void
      vmult(TrilinosWrappers::MPI::BlockVector       &dst,
            const TrilinosWrappers::MPI::BlockVector &src) const
      {
        // x_p = -S^-1 r_p
        laplace_amg.vmult(dst.block(1), src.block(1));
        TrilinosWrappers::MPI::Vector mass_part(src.block(1));
        mass_part.scale(scaled_inverse_mass);
        dst.block(1) += mass_part;
        dst.block(1) *= -1;
        // x_u = A^-1 (r_u - B^T x_p)
        system.block(0, 1).vmult(tmp, dst.block(1));
        tmp.sadd(-1, src.block(0));
        velocity_amg.vmult(dst.block(0), tmp);
      }

    private:
      const TrilinosWrappers::BlockSparseMatrix &system;
      const TrilinosWrappers::PreconditionAMG   &velocity_amg;
      const TrilinosWrappers::PreconditionAMG   &laplace_amg;
      const TrilinosWrappers::MPI::Vector       &scaled_inverse_mass;
      mutable TrilinosWrappers::MPI::Vector      tmp;
    };
  } // namespace

  template <int dim>
  StokesStep<dim>::StokesStep(
    const FlowStepParameters                        &parameters,
    const Rheology<dim>                             &rheology,
    const parallel::distributed::Triangulation<dim> &triangulation)
    : parameters(parameters)
    , comm(triangulation.get_communicator())
    , dof_handler(triangulation)
    , rheology(rheology)
    , contact(parameters.cavity)
    , elements(parameters.flow,
               parameters.max_level,
               parameters.flow.finest_at_contact_walls
                 ? contact.boundary_ids()
                 : std::vector<types::boundary_id>())
  {
    fe_collection.push_back(FESystem<dim>(FE_Q<dim>(1), dim, FE_Q<dim>(1), 1));
    fe_collection.push_back(
      FESystem<dim>(FE_Nothing<dim>(), dim, FE_Nothing<dim>(), 1));
    for (unsigned int w = 0; w < 2 * dim; ++w)
      if (parameters.cavity.wall_type[w] == WallType::velocity)
        wall_velocity[w] = make_wall_velocity<dim>(parameters.cavity, w);
  }

  template <int dim>
  void
  StokesStep<dim>::setup(const LiquidDomain<dim> &domain, const double new_time)
  {
    time         = new_time;
    this->domain = &domain;
    step_systems.reset();
    elements.classify(dof_handler, domain);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        cell->set_active_fe_index(elements.has_liquid(cell) ? liquid_index
                                                            : empty_index);
    dof_handler.distribute_dofs(fe_collection);
    numbering = renumber_flow_dofs(dof_handler, elements, liquid_index);

    DoFTools::extract_locally_relevant_dofs(dof_handler, relevant_dofs);
    owned_partitioning =
      numbering.flow_blocks(dof_handler.locally_owned_dofs());
    relevant_partitioning = numbering.flow_blocks(relevant_dofs);
    elements.exchange_element_dofs(dof_handler, liquid_index, relevant_dofs);
    touched_dofs = relevant_dofs;
    touched_dofs.add_indices(elements.far_element_dofs());
    touched_partitioning = numbering.flow_blocks(touched_dofs);
    check_periodic_liquid();
    interpolation.clear();
    interpolation.reinit(touched_dofs);
    elements.make_interpolation_constraints(dof_handler,
                                            liquid_index,
                                            interpolation);
    // The velocity block comes first: its indices are the global ones.
    contact.reset(dof_handler,
                  owned_partitioning[0],
                  relevant_partitioning[0],
                  touched_partitioning[0],
                  liquid_index,
                  interpolation);
    make_constraints();
    make_matrices();
  }

  template <int dim>
  void
  StokesStep<dim>::check_periodic_liquid() const
  {
    const auto directions = parameters.cavity.periodic_directions();
    if (directions.empty())
      return;
    bool mismatch = false;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && cell->at_boundary())
        for (const unsigned int f : cell->face_indices())
          if (cell->has_periodic_neighbor(f))
            {
              const auto neighbor = cell->periodic_neighbor(f);
              if (neighbor->has_children())
                {
                  for (unsigned int c = 0;
                       c < GeometryInfo<dim>::max_children_per_face;
                       ++c)
                    if (cell->periodic_neighbor_child_on_subface(f, c)
                          ->active_fe_index() != cell->active_fe_index())
                      mismatch = true;
                }
              else if (neighbor->active_fe_index() != cell->active_fe_index())
                mismatch = true;
            }
    if (Utilities::MPI::logical_or(mismatch, comm))
      throw InputError(
        "entry 'Walls/" + wall_names[2 * directions[0]] +
        "': the liquid meets empty space across the periodic walls; a free "
        "surface that crosses a periodic wall is not supported in this "
        "version: the liquid must meet liquid there (at t = " +
        [this]() {
          std::ostringstream t;
          t << std::setprecision(6) << time;
          return t.str();
        }() +
        " s)");
  }

  template <int dim>
  void
  StokesStep<dim>::make_constraints()
  {
    // The flow's space first: the interpolation in the cells on a coarser
    // element, then what constrains the space's own unknowns.
    constraints.clear();
    constraints.copy_from(interpolation);
    DoFTools::make_hanging_node_constraints(dof_handler, constraints);
    for (const unsigned int d : parameters.cavity.periodic_directions())
      DoFTools::make_periodicity_constraints(dof_handler,
                                             2 * d,
                                             2 * d + 1,
                                             d,
                                             constraints);
    make_wall_constraints(constraints);
    make_far_element_wall_constraints(constraints);
    // A periodic pair may be split between ranks, and the walls it meets
    // constrain the same nodes: each rank must know the constraints of the
    // other side. (Several ranks allow one periodic pair only.)
    if (!parameters.cavity.periodic_directions().empty() &&
        Utilities::MPI::n_mpi_processes(comm) > 1)
      constraints.make_consistent_in_parallel(dof_handler.locally_owned_dofs(),
                                              relevant_dofs,
                                              comm);
    constraints.close();

    // The flow space's own unknowns are constrained by its own only (the
    // interpolated ones are not in its matrices), pressures by pressures
    // only (hanging nodes, interpolation on coarser elements). The owned
    // constrained ones are kept for the solves, which start from zero there.
    const types::global_dof_index n_u    = numbering.n_velocities();
    const types::global_dof_index n_flow = numbering.n_flow_dofs();
    const IndexSet               &owned  = dof_handler.locally_owned_dofs();
    pressure_constraints.clear();
    pressure_constraints.reinit(touched_partitioning[1]);
    owned_constrained_flow_dofs.clear();
    for (const auto &line : constraints.get_lines())
      if (line.index < n_flow)
        {
          if (owned.is_element(line.index))
            owned_constrained_flow_dofs.push_back(line.index);
          const bool pressure = line.index >= n_u;
          if (pressure)
            pressure_constraints.add_line(line.index - n_u);
          for (const auto &[column, weight] : line.entries)
            {
              AssertThrow(column < n_flow && (column >= n_u) == pressure,
                          ExcInternalError());
              if (pressure)
                pressure_constraints.add_entry(line.index - n_u,
                                               column - n_u,
                                               weight);
            }
        }
    pressure_constraints.close();
  }

  template <int dim>
  void
  StokesStep<dim>::make_matrices()
  {
    // Built in deal.II's pattern and handed to Epetra once: inserting the
    // entries of each cell and face into Epetra's graph one by one took most
    // of the setup of the 3D ball. The entries are those the assembly
    // adds: a coarser element couples its vertices' unknowns once (through
    // the constraints of its cells it took 4 % of a step at 2.5 mm); the
    // interpolated unknowns of its cells have no rows (FlowNumbering).
    BlockDynamicSparsityPattern          pattern(touched_partitioning);
    const FiniteElement<dim>            &fe = fe_collection[liquid_index];
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && cell->active_fe_index() == liquid_index)
        {
          if (!elements.on_coarser_element(cell))
            cell->get_dof_indices(dofs);
          else if (elements.represents_element(cell))
            for (unsigned int i = 0; i < dofs.size(); ++i)
              {
                const auto [component, vertex] =
                  fe.system_to_component_index(i);
                dofs[i] = elements.element_vertex_dof(cell, vertex, component);
              }
          else
            continue;
          constraints.add_entries_local_to_global(dofs, pattern, false);
        }
    // The ghost penalty couples the two cells of a face.
    GhostPenalty<dim> ghost_penalty(parameters,
                                    rheology,
                                    fe_collection[liquid_index],
                                    elements,
                                    1.);
    ghost_penalty.for_each_face(
      dof_handler,
      false,
      [&](const auto &, const auto &, const auto &dofs) {
        constraints.add_entries_local_to_global(dofs, pattern, false);
      });
    const types::global_dof_index n_flow = numbering.n_flow_dofs();
    SparsityTools::distribute_sparsity_pattern(
      pattern,
      dof_handler.locally_owned_dofs().get_view(0, n_flow),
      comm,
      touched_dofs.get_view(0, n_flow));
    make_owned_rows_matrix(pattern, owned_partitioning, comm, system_matrix);

    // The Schur approximation couples the pressures as the pressure block of
    // the system does (cells and ghost penalty alike): the two share the
    // Epetra graph.
    schur_matrix.clear();
    schur_matrix.reinit(system_matrix.block(1, 1));

    system_rhs.reinit(owned_partitioning, comm);
    lumped_pressure_mass.reinit(owned_partitioning, comm);
    flow_solution.reinit(owned_partitioning, comm);
    // All parts, the interpolated too; touched: the contact reactions of
    // faces read far element vertices.
    const std::vector<IndexSet> owned_parts =
      numbering.all_parts(dof_handler.locally_owned_dofs());
    owned_solution.reinit(owned_parts, comm);
    solution.reinit(owned_parts, numbering.all_parts(touched_dofs), comm);
    constraint_distribution.reinit(constraints, owned_solution, solution);
  }

  template <int dim>
  void
  StokesStep<dim>::make_far_element_wall_constraints(
    AffineConstraints<double> &constraints) const
  {
    const IndexSet &far = elements.far_element_dofs();
    if (far.is_empty())
      return;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (const auto element = elements.element(cell);
          cell->is_ghost() && cell->active_fe_index() == liquid_index &&
          elements.on_coarser_element(cell) && element->at_boundary())
        for (const unsigned int f : element->face_indices())
          if (element->at_boundary(f))
            {
              const types::boundary_id wall = element->face(f)->boundary_id();
              const WallType           type = parameters.cavity.wall_type[wall];
              if (type != WallType::no_slip && type != WallType::slip &&
                  type != WallType::velocity)
                continue;
              if (type == WallType::velocity)
                wall_velocity[wall]->set_time(time);
              for (unsigned int i = 0; i < GeometryInfo<dim>::vertices_per_face;
                   ++i)
                {
                  const unsigned int v =
                    GeometryInfo<dim>::face_to_cell_vertices(f, i);
                  for (unsigned int c = 0; c < dim; ++c)
                    {
                      // A slip wall holds the normal component only.
                      if (type == WallType::slip && c != wall / 2)
                        continue;
                      const types::global_dof_index dof =
                        elements.element_vertex_dof(cell, v, c);
                      if (!far.is_element(dof) ||
                          constraints.is_constrained(dof))
                        continue;
                      constraints.add_line(dof);
                      if (type == WallType::velocity)
                        constraints.set_inhomogeneity(
                          dof,
                          wall_velocity[wall]->value(element->vertex(v), c));
                    }
                }
            }
  }

  template <int dim>
  void
  StokesStep<dim>::make_wall_constraints(
    AffineConstraints<double> &constraints) const
  {
    const FEValuesExtractors::Vector velocity(0);
    for (unsigned int w = 0; w < 2 * dim; ++w)
      {
        const types::boundary_id id = w;
        switch (parameters.cavity.wall_type[w])
          {
            case WallType::no_slip:
              VectorTools::interpolate_boundary_values(
                dof_handler,
                id,
                Functions::ZeroFunction<dim>(dim + 1),
                constraints,
                fe_collection.component_mask(velocity));
              break;
            case WallType::slip:
              {
                // Axis-aligned wall: the normal component is one velocity
                // component.
                std::vector<bool> normal(dim + 1, false);
                normal[w / 2] = true;
                VectorTools::interpolate_boundary_values(
                  dof_handler,
                  id,
                  Functions::ZeroFunction<dim>(dim + 1),
                  constraints,
                  ComponentMask(normal));
                break;
              }
            case WallType::velocity:
              {
                wall_velocity[w]->set_time(time);
                VectorTools::interpolate_boundary_values(
                  dof_handler,
                  id,
                  FlowBoundaryValues<dim>(*wall_velocity[w]),
                  constraints,
                  fe_collection.component_mask(velocity));
                break;
              }
            case WallType::open:
            case WallType::periodic:
            case WallType::contact: // the contact set, see ContactWalls
              break;
          }
      }
  }

  template <int dim>
  void
  StokesStep<dim>::assemble(const TransportedFields<dim> &fields,
                            const double                  tau)
  {
    system_matrix        = 0;
    schur_matrix         = 0;
    system_rhs           = 0;
    lumped_pressure_mass = 0;

    StepSystems                         &systems = systems_of_step(fields, tau);
    StokesCellSystem<dim>               &local   = systems.cells;
    std::vector<types::global_dof_index> dof_indices(
      fe_collection[liquid_index].n_dofs_per_cell());

    const FiniteElement<dim>       &fe = fe_collection[liquid_index];
    const unsigned int              n  = fe.n_dofs_per_cell();
    FullMatrix<double>              element_matrix(n, n), element_schur(n, n);
    Vector<double>                  element_rhs(n), element_pressure_mass(n);
    const std::vector<unsigned int> pressure_only = {dim};

    // The pressure rows and columns of a local Schur matrix, in the
    // numbering of the pressure block (after all velocities).
    const types::global_dof_index        n_u = owned_partitioning[0].size();
    std::vector<types::global_dof_index> pressure_dofs;
    std::vector<unsigned int>            pressure_rows;
    FullMatrix<double>                   pressure_schur;
    const auto                           add_to_schur =
      [&](const FullMatrix<double>                   &schur,
          const std::vector<types::global_dof_index> &dofs) {
        pressure_dofs.clear();
        pressure_rows.clear();
        for (unsigned int i = 0; i < dofs.size(); ++i)
          if (dofs[i] >= n_u)
            {
              pressure_dofs.push_back(dofs[i] - n_u);
              pressure_rows.push_back(i);
            }
        pressure_schur.reinit(pressure_rows.size(), pressure_rows.size());
        pressure_schur.extract_submatrix_from(schur,
                                              pressure_rows,
                                              pressure_rows);
        pressure_constraints.distribute_local_to_global(pressure_schur,
                                                        pressure_dofs,
                                                        schur_matrix);
      };
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && !elements.on_coarser_element(cell) &&
          domain->has_liquid(cell))
        {
          local.compute(cell);
          cell->get_dof_indices(dof_indices);
          local.apply_pressure_mass_floor(local.pressure_mass, cell->measure());
          constraints.distribute_local_to_global(local.matrix,
                                                 local.rhs,
                                                 dof_indices,
                                                 system_matrix,
                                                 system_rhs);
          add_to_schur(local.schur, dof_indices);
          constraints.distribute_local_to_global(local.pressure_mass,
                                                 dof_indices,
                                                 lumped_pressure_mass);
        }
      else if (cell->is_locally_owned() && elements.on_coarser_element(cell) &&
               elements.represents_element(cell))
        {
          // A coarser element: its cells' systems summed in the element's
          // unknowns, then added once (the same sums as through the
          // interpolation constraints, without expanding every entry).
          element_matrix        = 0;
          element_schur         = 0;
          element_rhs           = 0;
          element_pressure_mass = 0;
          bool       any_liquid = false;
          const auto element    = elements.element(cell);
          for (const auto &other : elements.cells_of(element))
            {
              if (!other->is_locally_owned() || !domain->has_liquid(other))
                continue;
              any_liquid = true;
              local.compute(other);
              elements.add_restricted_to_element(fe,
                                                 other,
                                                 local.matrix,
                                                 element_matrix);
              elements.add_restricted_to_element(fe,
                                                 other,
                                                 local.schur,
                                                 element_schur,
                                                 pressure_only);
              elements.add_restricted_to_element(fe,
                                                 other,
                                                 local.rhs,
                                                 element_rhs);
              elements.add_restricted_to_element(fe,
                                                 other,
                                                 local.pressure_mass,
                                                 element_pressure_mass);
            }
          if (!any_liquid)
            continue;
          for (unsigned int i = 0; i < n; ++i)
            {
              const auto [component, vertex] = fe.system_to_component_index(i);
              dof_indices[i] =
                elements.element_vertex_dof(cell, vertex, component);
            }
          local.apply_pressure_mass_floor(element_pressure_mass,
                                          element->measure());
          constraints.distribute_local_to_global(element_matrix,
                                                 element_rhs,
                                                 dof_indices,
                                                 system_matrix,
                                                 system_rhs);
          add_to_schur(element_schur, dof_indices);
          constraints.distribute_local_to_global(element_pressure_mass,
                                                 dof_indices,
                                                 lumped_pressure_mass);
        }

    Vector<double> zero_rhs;
    systems.faces.for_each_face(
      dof_handler,
      true,
      [&](const auto &matrix, const auto &schur, const auto &dofs) {
        // Through the right-hand side, so that wall velocities act.
        zero_rhs.reinit(dofs.size());
        constraints.distribute_local_to_global(matrix,
                                               zero_rhs,
                                               dofs,
                                               system_matrix,
                                               system_rhs);
        add_to_schur(schur, dofs);
      });
    system_matrix.compress(VectorOperation::add);
    schur_matrix.compress(VectorOperation::add);
    system_rhs.compress(VectorOperation::add);
    lumped_pressure_mass.compress(VectorOperation::add);
    if (!contact.empty())
      contact.keep_rows(system_matrix, system_rhs, constraints);
  }

  namespace
  {
    /** An ML hierarchy as @p data describes it, with a coarse grid of at most
     * @p coarse_rows rows (factorised by KLU on one rank). */
    void
    initialize_amg(
      TrilinosWrappers::PreconditionAMG                       &amg,
      const TrilinosWrappers::SparseMatrix                    &matrix,
      const TrilinosWrappers::PreconditionAMG::AdditionalData &data,
      const int                                                coarse_rows)
    {
      Teuchos::ParameterList              ml_parameters;
      std::unique_ptr<Epetra_MultiVector> near_kernel;
      data.set_parameters(ml_parameters, near_kernel, matrix);
      ml_parameters.set("coarse: max size", coarse_rows);
      amg.initialize(matrix, ml_parameters);
    }
  } // namespace

  template <int dim>
  void
  StokesStep<dim>::make_amg_hierarchies(StepSystems &systems) const
  {
    // AMG for the velocity block, told about the constant modes (one per
    // velocity component) so that aggregation treats them as near-kernel.
    std::vector<std::vector<bool>> constant_modes(dim);
    {
      const IndexSet &owned_u = owned_partitioning[0];
      for (unsigned int d = 0; d < dim; ++d)
        constant_modes[d].assign(owned_u.n_elements(), false);
      std::vector<types::global_dof_index> dof_indices;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned() && cell->active_fe_index() == liquid_index)
          {
            const auto &fe = cell->get_fe();
            dof_indices.resize(fe.n_dofs_per_cell());
            cell->get_dof_indices(dof_indices);
            for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
              {
                const unsigned int c = fe.system_to_component_index(i).first;
                if (c < dim && dof_indices[i] < owned_u.size() &&
                    owned_u.is_element(dof_indices[i]))
                  constant_modes[c][owned_u.index_within_set(dof_indices[i])] =
                    true;
              }
          }
    }
    TrilinosWrappers::PreconditionAMG::AdditionalData velocity_data;
    velocity_data.elliptic              = true;
    velocity_data.higher_order_elements = false;
    velocity_data.smoother_sweeps       = parameters.solver.amg_smoother_sweeps;
    // With the flow on the parents: the first 10 steps of the 3D ball at
    // 2.5 mm take 119 Krylov iterations with 0.05, 121 with 0.02 (before the
    // interpolated unknowns left the matrix, each a row of its own
    // diagonal, the first step alone took 17 and 22).
    velocity_data.aggregation_threshold =
      parameters.flow.flow_level_offset > 0 ? 0.05 : 0.02;
    velocity_data.constant_modes = constant_modes;
    systems.velocity_amg =
      std::make_unique<TrilinosWrappers::PreconditionAMG>();
    // ML's coarse grid of up to 2000 rows, with dim near-kernel vectors per
    // aggregate, is nearly dense in 3D: its KLU factorisation on one rank
    // took 9 s of the 3D ball to t = 0.2 s on 1 rank and as much on 2.
    // At 500 rows the outer iterations are the same and the solve section
    // takes 15 s instead of 24 (1 rank) and 9 s instead of 17 (2 ranks). In
    // 2D the factorisation is cheap and 500 rows cost iterations (2D broken
    // dam: 2475 instead of 1542; the small grids of the tests, whose whole
    // velocity block fits in 2000 rows, 4 times more).
    initialize_amg(*systems.velocity_amg,
                   system_matrix.block(0, 0),
                   velocity_data,
                   dim == 3 ? 500 : 2000);

    // The same sweeps for the pressure Laplacian L_w: with ML's default of
    // 2, water's iterations grew once the AMG had more than one level (2D
    // broken dam, mu = 0.001 Pa s, 1 ms steps: 13.4 at level 7, 15.3 at
    // level 8); with 4 they stay flat (13.4, 13.1; 12.5 at level 9) at the
    // same solve time; the 3D dam's (level 5) fall from 21.7 to 17.4.
    TrilinosWrappers::PreconditionAMG::AdditionalData laplace_data;
    laplace_data.elliptic        = true;
    laplace_data.smoother_sweeps = parameters.solver.amg_smoother_sweeps;
    systems.laplace_amg = std::make_unique<TrilinosWrappers::PreconditionAMG>();
    systems.laplace_amg->initialize(schur_matrix, laplace_data);
  }

  template <int dim>
  void
  StokesStep<dim>::build_preconditioner()
  {
    Assert(step_systems,
           ExcMessage("build_preconditioner() after assemble()."));
    if (!step_systems->velocity_amg)
      make_amg_hierarchies(*step_systems);
  }

  template <int dim>
  unsigned int
  StokesStep<dim>::solve(const double tolerance)
  {
    Assert(step_systems, ExcMessage("solve() after assemble()."));
    StepSystems &systems           = *step_systems;
    const bool   contact_iteration = systems.n_solves > 0;
    ++systems.n_solves;
    build_preconditioner();

    TrilinosWrappers::MPI::Vector scaled_inverse_mass(
      lumped_pressure_mass.block(1));
    for (const auto i : scaled_inverse_mass.locally_owned_elements())
      {
        const double m         = lumped_pressure_mass.block(1)(i);
        scaled_inverse_mass(i) = m > 0 ? 1. / m : 0.;
      }
    scaled_inverse_mass.compress(VectorOperation::insert);

    const BlockPreconditioner preconditioner(system_matrix,
                                             *systems.velocity_amg,
                                             *systems.laplace_amg,
                                             scaled_inverse_mass);

    // A contact iteration starts from the solve before it, whose contact set
    // differs in a few unknowns only.
    BlockVector distributed(owned_partitioning, comm);
    if (contact_iteration)
      distributed = flow_solution;
    // The constrained unknowns of the flow space are zero in the Krylov
    // space (AffineConstraints::set_zero() would look for the interpolated
    // ones in it too).
    for (const auto dof : owned_constrained_flow_dofs)
      distributed(dof) = 0;
    distributed.compress(VectorOperation::insert);
    contact.set_zero(distributed);
    const double rhs_norm = system_rhs.l2_norm();
    // An overflowing right-hand side would make the tolerance infinite and
    // the zero vector a "converged" solution.
    if (!std::isfinite(rhs_norm))
      throw SolverError("the right-hand side of the Stokes step is not "
                        "finite; check 'Gravity', 'Material/Density', the "
                        "'Walls' velocities and 'Time/Time step'");
    SolverControl             control(parameters.solver.solver_max_iterations,
                          std::max(tolerance * rhs_norm, 1e-300));
    SolverFGMRES<BlockVector> solver(control,
                                     SolverFGMRES<BlockVector>::AdditionalData(
                                       100));
    try
      {
        if (rhs_norm > 0)
          solver.solve(system_matrix, distributed, system_rhs, preconditioner);
      }
    catch (const SolverControl::NoConvergence &failure)
      {
        std::ostringstream message;
        message << std::scientific << std::setprecision(2)
                << "the Stokes solver did not converge: residual "
                << failure.last_residual << " after " << failure.last_step
                << " iterations (tolerance " << control.tolerance()
                << " = 'Solver/"
                << (tolerance == parameters.solver.solver_tolerance
                      ? "Tolerance"
                      : "Contact tolerance")
                << "' times the right-hand side norm). "
                << "Reduce 'Time/Time step' or raise 'Solver/Maximum "
                << "iterations'.";
        throw SolverError(message.str());
      }
    // The rows in contact hold u.n = 0 to the solver's tolerance: exactly,
    // before the constraints that interpolate from them (read from the
    // ghosted solution).
    contact.set_zero(distributed);
    if (!std::isfinite(distributed.l2_norm()))
      throw SolverError("the Stokes solution is not finite; check "
                        "'Gravity', the 'Walls' velocities and 'Time/Time "
                        "step'");
    flow_solution = distributed;

    // Into all parts: the constrained unknowns, the interpolated ones
    // among them, from the flow space's own.
    for (unsigned int b = 0; b < 2; ++b)
      owned_solution.block(b) = distributed.block(b);
    solution = owned_solution;
    constraint_distribution.distribute(solution, owned_solution);
    solution = owned_solution;
    return control.last_step();
  }

  template <int dim>
  bool
  StokesStep<dim>::update_contact(const TransportedFields<dim> &fields,
                                  const double                  tau)
  {
    if (contact.empty())
      return false;
    StepSystems &systems = systems_of_step(fields, tau);
    if (!contact.update(dof_handler,
                        *domain,
                        solution,
                        systems.cells,
                        systems.faces,
                        elements,
                        interpolation))
      return false;
    contact.impose(system_matrix, system_rhs);
    return true;
  }

  template <int dim>
  typename StokesStep<dim>::StepSystems &
  StokesStep<dim>::systems_of_step(const TransportedFields<dim> &fields,
                                   const double                  tau)
  {
    Assert(!step_systems || step_systems->tau == tau,
           ExcMessage("One time step per setup()."));
    if (!step_systems)
      step_systems.reset(
        new StepSystems{StokesCellSystem<dim>(parameters,
                                              rheology,
                                              fe_collection[liquid_index],
                                              fields,
                                              *domain,
                                              elements,
                                              tau),
                        GhostPenalty<dim>(parameters,
                                          rheology,
                                          fe_collection[liquid_index],
                                          elements,
                                          tau),
                        tau,
                        nullptr,
                        nullptr});
    return *step_systems;
  }

  template <int dim>
  double
  StokesStep<dim>::face_flux(
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    const unsigned int                                    f,
    const Quadrature<dim>                                &wet) const
  {
    if (wet.size() == 0)
      return 0;
    // The Q1 velocity normal to the face at the wet points (the cells' own
    // Q1 values, as on the liquid parts of cut cells).
    const unsigned int                                       d = f / 2;
    std::array<double, GeometryInfo<dim>::vertices_per_cell> normal_velocity;
    for (const unsigned int v : cell->vertex_indices())
      normal_velocity[v] = solution(cell->vertex_dof_index(v, d, liquid_index));
    BoxCellValues<dim> values;
    values.reinit(cell, wet);
    double flux = 0;
    for (unsigned int q = 0; q < wet.size(); ++q)
      flux += values.value(normal_velocity, q) * wet.weight(q);
    // Outward normal +-e_d; the reference face maps to the face's area.
    return (f % 2 == 0 ? -1. : 1.) * flux * cell->face(f)->measure();
  }

  template <int dim>
  double
  StokesStep<dim>::outflow_rate() const
  {
    // A whole face by the Gauss rule on it, exact for the Q1 velocity; the
    // wet part of a cut cell's face by the rule of its liquid domain.
    std::vector<Quadrature<dim>> whole_faces;
    for (const unsigned int f : GeometryInfo<dim>::face_indices())
      whole_faces.push_back(
        QProjector<dim>::project_to_face(ReferenceCells::get_hypercube<dim>(),
                                         QGauss<dim - 1>(2),
                                         f));
    double rate = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && cell->at_boundary() &&
          domain->has_liquid(cell))
        for (const unsigned int f : cell->face_indices())
          if (cell->at_boundary(f) &&
              (parameters.cavity.wall_type[cell->face(f)->boundary_id()] ==
                 WallType::velocity ||
               parameters.cavity.wall_type[cell->face(f)->boundary_id()] ==
                 WallType::open))
            rate += face_flux(cell,
                              f,
                              domain->location(cell) ==
                                  LiquidDomain<dim>::Location::cut
                                ? domain->cut_cell(cell).wet_boundary_face(f)
                                : whole_faces[f]);
    return Utilities::MPI::sum(rate, comm);
  }

  template <int dim>
  double
  StokesStep<dim>::contact_power(const TransportedFields<dim> &fields) const
  {
    if (contact.empty())
      return 0;
    // The owned wall unknowns lie on owned cells at the boundary.
    std::map<types::global_dof_index, double> mid_velocity;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && cell->at_boundary() &&
          cell->active_fe_index() == liquid_index)
        {
          const auto transport_cell = fields.cell_of(cell);
          for (const unsigned int v : cell->vertex_indices())
            {
              const Tensor<1, dim> advected =
                fields.velocity_at(transport_cell, v);
              for (unsigned int d = 0; d < dim; ++d)
                {
                  const auto dof = cell->vertex_dof_index(v, d, liquid_index);
                  mid_velocity[dof] = 0.5 * (solution(dof) + advected[d]);
                }
            }
        }
    return contact.power([&](const types::global_dof_index dof) {
      const auto entry = mid_velocity.find(dof);
      return entry == mid_velocity.end() ? 0. : entry->second;
    });
  }

  template <int dim>
  void
  StokesStep<dim>::copy_velocity_to(
    TransportedFields<dim>                      &fields,
    typename TransportedFields<dim>::VectorType &known) const
  {
    known = 0;
    // Owned and ghost liquid cells: every owned node next to the liquid is a
    // vertex of one of them.
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (!cell->is_artificial() && cell->active_fe_index() == liquid_index)
        {
          const auto transport_cell = fields.cell_of(cell);
          for (const unsigned int v : cell->vertex_indices())
            {
              // Local entries below the owned size are owned.
              const unsigned int first =
                fields.local_entry(transport_cell, v, 0);
              if (first >= fields.partitioner->locally_owned_size())
                continue;
              Tensor<1, dim> u;
              for (unsigned int d = 0; d < dim; ++d)
                u[d] = solution(cell->vertex_dof_index(v, d, liquid_index));
              fields.set_velocity_at(transport_cell, v, u);
              known.local_element(first) = 1;
            }
        }
    fields.finalize();
    known.update_ghost_values();
  }

  template class StokesStep<2>;
  template class StokesStep<3>;
} // namespace vefs
