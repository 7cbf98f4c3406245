#include <vefs/flow/stokes_cell_system.h>

namespace vefs
{
  template <int dim>
  StokesCellSystem<dim>::StokesCellSystem(const FlowStepParameters &parameters,
                                          const Rheology<dim>      &rheology,
                                          const FiniteElement<dim> &flow_fe,
                                          const TransportedFields<dim> &fields,
                                          const LiquidDomain<dim>      &domain,
                                          const FlowElements<dim> &elements,
                                          const double             tau)
    : parameters(parameters)
    , rheology(rheology)
    , fields(fields)
    , domain(domain)
    , elements(elements)
    , flow_fe(flow_fe)
    , tau(tau)
    , mass_tau(parameters.mass_step(tau))
    , old_force_step(parameters.old_force_step(tau))
    , mu(rheology.effective_viscosity(tau))
    , sigma_star_factor(rheology.explicit_stress_factor(tau))
    , geometric_factor(rheology.geometric_factor(tau))
    , with_explicit_strain(rheology.has_stress() &&
                           rheology.implicit_weight() < 1)
    , liquid_values(domain)
    , face_values(flow_fe,
                  QGauss<dim - 1>(2),
                  update_values | update_JxW_values)
    , kept_index(fields.dof_handler.get_triangulation().n_active_cells(),
                 numbers::invalid_unsigned_int)
  {
    for (unsigned int d = 0; d < dim; ++d)
      gravity[d] = parameters.material.gravity[d];
    double diameter_squared = 0;
    for (unsigned int d = 0; d < dim; ++d)
      diameter_squared += std::pow(parameters.cavity.cavity_upper[d] -
                                     parameters.cavity.cavity_lower[d],
                                   2);
    // A small mass term keeps the Schur Laplacian regular without a surface.
    regularization = 1e-3 / diameter_squared;

    const unsigned int n_dofs = flow_fe.n_dofs_per_cell();
    matrix.reinit(n_dofs, n_dofs);
    schur.reinit(n_dofs, n_dofs);
    rhs.reinit(n_dofs);
    pressure_mass.reinit(n_dofs);
    component.resize(n_dofs);
    vertex.resize(n_dofs);
    for (unsigned int i = 0; i < n_dofs; ++i)
      {
        component[i] = flow_fe.system_to_component_index(i).first;
        // FE_Q(1): the dof of a base element is that of the vertex.
        vertex[i] = flow_fe.system_to_component_index(i).second;
        if (component[i] == dim)
          pressure_dofs.push_back(i);
      }
    for (unsigned int i = 0; i < n_dofs; ++i)
      dof_of[component[i]][vertex[i]] = i;
  }

  template <int dim>
  void
  StokesCellSystem<dim>::compute(
    const typename DoFHandler<dim>::active_cell_iterator &cell)
  {
    const unsigned int index = kept_index[cell->active_cell_index()];
    if (index != numbers::invalid_unsigned_int)
      recall(kept_cells[index]);
    else
      {
        compute_anew(cell);
        // The contact walls need the cells of elements at the walls.
        if (elements.element(cell)->at_boundary())
          keep(cell);
      }
  }

  template <int dim>
  void
  StokesCellSystem<dim>::keep(
    const typename DoFHandler<dim>::active_cell_iterator &cell)
  {
    kept_index[cell->active_cell_index()] = kept_cells.size();
    KeptCell kept_cell{matrix,
                       rhs,
                       FullMatrix<double>(pressure_dofs.size()),
                       pressure_mass,
                       schur_weight};
    kept_cell.pressure_schur.extract_submatrix_from(schur,
                                                    pressure_dofs,
                                                    pressure_dofs);
    kept_cells.push_back(std::move(kept_cell));
  }

  template <int dim>
  void
  StokesCellSystem<dim>::recall(const KeptCell &kept_cell)
  {
    matrix        = kept_cell.matrix;
    rhs           = kept_cell.rhs;
    pressure_mass = kept_cell.pressure_mass;
    schur_weight  = kept_cell.schur_weight;
    schur         = 0;
    kept_cell.pressure_schur.scatter_matrix_to(pressure_dofs,
                                               pressure_dofs,
                                               schur);
  }

  template <int dim>
  void
  StokesCellSystem<dim>::compute_anew(
    const typename DoFHandler<dim>::active_cell_iterator &cell)
  {
    const bool   with_stress = rheology.has_stress();
    const double rho         = parameters.material.density;

    const bool is_cut =
      domain.location(cell) == LiquidDomain<dim>::Location::cut;
    const BoxCellValues<dim> &values = liquid_values.reinit(cell);
    evaluate_advected_fields(values, fields.cell_of(cell));

    const double h     = elements.size(cell);
    const double tau_K = parameters.solver.pressure_stabilization /
                         (rho / mass_tau + 4 * mu / (h * h));
    schur_weight = mass_tau / rho + tau_K;

    matrix        = 0;
    schur         = 0;
    rhs           = 0;
    pressure_mass = 0;
    if (is_cut)
      add_surface_terms(cell, h);

    const unsigned int n_vertices  = BoxCellValues<dim>::n_vertices;
    const double       mass_factor = rho / mass_tau;
    for (unsigned int q = 0; q < values.size(); ++q)
      {
        // Every dof is the Q1 function N of its vertex in one component, so
        // the cell matrix follows from products of N and grad N per vertex
        // pair; written out, the assembly costs a fraction of the tensor
        // algebra over all dof pairs.
        const auto  &N   = values.shape[q];
        const auto  &G   = values.gradient[q];
        const double JxW = values.JxW[q];
        for (unsigned int I = 0; I < n_vertices; ++I)
          pressure_mass(dof_of[dim][I]) += N[I] * JxW / mu;
        const Tensor<1, dim> forcing = mass_factor * u_star[q] + rho * gravity;
        // The explicit part of the stress, div sigma* times its factor, is
        // a force in the strong residual of the pressure stabilisation.
        Tensor<1, dim>          stabilized_forcing = forcing;
        SymmetricTensor<2, dim> explicit_stress;
        if (with_stress)
          {
            stabilized_forcing += sigma_star_factor * div_sigma_star[q];
            explicit_stress = sigma_star_factor * sigma_star[q];
            if (with_explicit_strain)
              explicit_stress += rheology.explicit_strain_stress(sigma_star[q],
                                                                 grad_u_star[q],
                                                                 tau);
            for (unsigned int J = 0; J < n_vertices; ++J)
              sigma_gradient[J] = sigma_star[q] * G[J];
          }
        for (unsigned int I = 0; I < n_vertices; ++I)
          {
            for (unsigned int J = 0; J < n_vertices; ++J)
              {
                const double NN = N[I] * N[J];
                const double GG = G[I] * G[J];
                // u-u: rho/tau N N + 2 mu eps : eps, and the geometric term
                // 2 theta^2 k tau (grad u sigma*) : eps(v) (its factor
                // geometric_factor):
                // mu (delta_ab G_I.G_J + G_I,b G_J,a)
                // + k/2 (delta_ab (sigma G_J).G_I + G_I,b (sigma G_J)_a).
                double diagonal = mass_factor * NN + mu * GG;
                if (with_stress)
                  diagonal +=
                    0.5 * geometric_factor * (sigma_gradient[J] * G[I]);
                for (unsigned int a = 0; a < dim; ++a)
                  {
                    const unsigned int i = dof_of[a][I];
                    for (unsigned int b = 0; b < dim; ++b)
                      {
                        double a_ij = mu * G[I][b] * G[J][a];
                        if (with_stress)
                          a_ij += 0.5 * geometric_factor * G[I][b] *
                                  sigma_gradient[J][a];
                        if (a == b)
                          a_ij += diagonal;
                        matrix(i, dof_of[b][J]) += a_ij * JxW;
                      }
                    // u-p: -(div v) p.
                    matrix(i, dof_of[dim][J]) -= G[I][a] * N[J] * JxW;
                    // p-u: -q div u and the PSPG term of rho/tau u.
                    matrix(dof_of[dim][I], dof_of[a][J]) -=
                      (N[I] * G[J][a] + tau_K * mass_factor * N[J] * G[I][a]) *
                      JxW;
                  }
                // p-p: the PSPG Laplacian; the Schur preconditioner's.
                const unsigned int i = dof_of[dim][I];
                const unsigned int j = dof_of[dim][J];
                matrix(i, j) -= tau_K * GG * JxW;
                schur(i, j) += schur_weight * (GG + regularization * NN) * JxW;
              }
            for (unsigned int a = 0; a < dim; ++a)
              {
                rhs(dof_of[a][I]) += forcing[a] * N[I] * JxW;
                if (with_stress)
                  rhs(dof_of[a][I]) -= (explicit_stress * G[I])[a] * JxW;
              }
            rhs(dof_of[dim][I]) -= tau_K * (stabilized_forcing * G[I]) * JxW;
          }
      }
    if (is_cut)
      add_small_cut_cell_mass(cell, mass_factor);
    // pressure_mass is the lumped mass of the liquid part (with the whole
    // cell's, the mass of the staircase, the viscous regime took 1.6 times
    // the iterations on fine meshes: mu = 10 Pa s, L = 8, 25.6 against 16.5
    // per step); the assembly raises it per flow element
    // (apply_pressure_mass_floor).
    add_open_wall_terms(cell, h);
  }

  template <int dim>
  void
  StokesCellSystem<dim>::apply_pressure_mass_floor(
    Vector<double> &element_pressure_mass,
    const double    element_measure) const
  {
    const unsigned int n_vertices = BoxCellValues<dim>::n_vertices;
    for (unsigned int i = 0; i < element_pressure_mass.size(); ++i)
      if (component[i] == dim)
        element_pressure_mass(i) =
          std::max(element_pressure_mass(i),
                   min_pressure_mass_fraction * element_measure / n_vertices /
                     mu);
  }

  template <int dim>
  void
  StokesCellSystem<dim>::add_open_wall_terms(
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    const double                                          h)
  {
    const FEValuesExtractors::Scalar pressure(dim);
    const unsigned int               n_dofs = matrix.m();
    for (const unsigned int f : cell->face_indices())
      if (cell->at_boundary(f) &&
          parameters.cavity.wall_type[cell->face(f)->boundary_id()] ==
            WallType::open)
        {
          face_values.reinit(cell, f);
          for (const unsigned int q : face_values.quadrature_point_indices())
            for (unsigned int i = 0; i < n_dofs; ++i)
              for (unsigned int j = 0; j < n_dofs; ++j)
                schur(i, j) += surface_penalty * schur_weight / h *
                               face_values[pressure].value(i, q) *
                               face_values[pressure].value(j, q) *
                               face_values.JxW(q);
        }
  }

  template <int dim>
  void
  StokesCellSystem<dim>::evaluate_advected_fields(
    const BoxCellValues<dim>                             &values,
    const typename DoFHandler<dim>::active_cell_iterator &transport_cell)
  {
    // The transported fields are Q1 on the same cell: their values follow
    // from the vertex values and the Q1 shape functions at these points.
    const unsigned int n_q         = values.size();
    const bool         with_stress = rheology.has_stress();
    u_star.assign(n_q, Tensor<1, dim>());
    u_star_at_vertex.resize(transport_cell->n_vertices());
    if (with_stress)
      {
        sigma_star.assign(n_q, SymmetricTensor<2, dim>());
        div_sigma_star.assign(n_q, Tensor<1, dim>());
      }
    if (with_explicit_strain)
      grad_u_star.assign(n_q, Tensor<2, dim>());
    for (const unsigned int v : transport_cell->vertex_indices())
      {
        Tensor<1, dim> u = fields.velocity_at(transport_cell, v);
        // The second-order scheme's old forces join the mass term:
        // rho / (w tau) (u* + (1 - w) tau a*), w the new forces' weight.
        Tensor<1, dim> u_with_old_forces = u;
        if (fields.has_acceleration())
          u_with_old_forces +=
            old_force_step * fields.acceleration_at(transport_cell, v);
        u_star_at_vertex[v] = u_with_old_forces;
        const SymmetricTensor<2, dim> sigma =
          with_stress ? fields.stress_at(transport_cell, v)
                      : SymmetricTensor<2, dim>();
        for (unsigned int q = 0; q < n_q; ++q)
          {
            const double phi = values.shape[q][v];
            u_star[q] += phi * u_with_old_forces;
            if (with_explicit_strain)
              grad_u_star[q] += outer_product(u, values.gradient[q][v]);
            if (with_stress)
              {
                sigma_star[q] += phi * sigma;
                div_sigma_star[q] += sigma * values.gradient[q][v];
              }
          }
      }
  }

  template <int dim>
  void
  StokesCellSystem<dim>::add_small_cut_cell_mass(
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    const double                                          mass_factor)
  {
    // A vanishing liquid part leaves its vertices with a vanishing mass
    // where no ghost-penalty face reaches them: the missing mass, lumped,
    // moves with u* (doc/time_step_flow.md, step 7).
    const double missing = parameters.solver.small_cut_cell_mass -
                           domain.fractions()[cell->active_cell_index()];
    if (missing <= 0)
      return;
    const unsigned int n_vertices = BoxCellValues<dim>::n_vertices;
    const double mass = missing * mass_factor * cell->measure() / n_vertices;
    for (unsigned int I = 0; I < n_vertices; ++I)
      for (unsigned int a = 0; a < dim; ++a)
        {
          const unsigned int i = dof_of[a][I];
          matrix(i, i) += mass;
          rhs(i) += mass * u_star_at_vertex[I][a];
        }
  }

  template <int dim>
  void
  StokesCellSystem<dim>::add_surface_terms(
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    const double                                          h)
  {
    surface_values.reinit(cell, domain.cut_cell(cell).surface);
    const unsigned int n_dofs = matrix.m();
    const double       theta  = parameters.solver.free_surface_stabilization;
    for (unsigned int q = 0; q < surface_values.size(); ++q)
      {
        const double          JxW    = surface_values.JxW[q];
        const Tensor<1, dim> &normal = surface_values.normal[q];
        const auto           &phi    = surface_values.shape[q];
        // The weight of the stabilisation: theta tau rho |g.n| where gravity
        // presses the surface back (g.n < 0, n pointing out of the liquid);
        // zero elsewhere, where the term would weaken the mass matrix.
        const double weight = theta * tau * parameters.material.density *
                              std::max(-(gravity * normal), 0.);
        for (unsigned int i = 0; i < n_dofs; ++i)
          for (unsigned int j = 0; j < n_dofs; ++j)
            if (component[i] == dim && component[j] == dim)
              // In the Schur preconditioner the pressure vanishes on the
              // free surface (zero traction): a penalty there keeps L_w
              // regular.
              schur(i, j) += surface_penalty * schur_weight / h *
                             phi[vertex[i]] * phi[vertex[j]] * JxW;
            else if (weight > 0 && component[i] < dim && component[j] < dim)
              matrix(i, j) += weight * (phi[vertex[i]] * normal[component[i]]) *
                              (phi[vertex[j]] * normal[component[j]]) * JxW;
      }
  }

  template class StokesCellSystem<2>;
  template class StokesCellSystem<3>;
} // namespace vefs
