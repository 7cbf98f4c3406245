#include <vefs/stokes_cell_system.h>

namespace vefs
{
  template <int dim>
  StokesCellSystem<dim>::StokesCellSystem(const Parameters         &parameters,
                                          const Rheology<dim>      &rheology,
                                          const FiniteElement<dim> &flow_fe,
                                          const TransportedFields<dim> &fields,
                                          const LiquidDomain<dim>      &domain,
                                          const double                  tau)
    : parameters(parameters)
    , rheology(rheology)
    , fields(fields)
    , domain(domain)
    , flow_fe(flow_fe)
    , tau(tau)
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
      gravity[d] = parameters.gravity[d];
    double diameter_squared = 0;
    for (unsigned int d = 0; d < dim; ++d)
      diameter_squared +=
        std::pow(parameters.cavity_upper[d] - parameters.cavity_lower[d], 2);
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
    stretching.resize(n_dofs);
    grad_u.resize(n_dofs);
    phi_u.resize(n_dofs);
    eps_u.resize(n_dofs);
    div_u.resize(n_dofs);
    phi_p.resize(n_dofs);
    grad_p.resize(n_dofs);
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
        if (cell->at_boundary())
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
    const bool         with_stress = rheology.has_stress();
    const unsigned int n_dofs      = matrix.m();
    const double       rho         = parameters.density;

    const bool is_cut =
      domain.location(cell) == LiquidDomain<dim>::Location::cut;
    const BoxCellValues<dim> &values = liquid_values.reinit(cell);
    evaluate_advected_fields(values, fields.cell_of(cell));

    const double h = cell->minimum_vertex_distance();
    const double tau_K =
      parameters.pressure_stabilization / (rho / tau + 4 * mu / (h * h));
    schur_weight = tau / rho + tau_K;

    matrix        = 0;
    schur         = 0;
    rhs           = 0;
    pressure_mass = 0;
    if (is_cut)
      add_surface_terms(cell, h);

    for (unsigned int q = 0; q < values.size(); ++q)
      {
        // Each shape function is the Q1 function of its vertex in one
        // component.
        for (unsigned int k = 0; k < n_dofs; ++k)
          {
            const double          phi  = values.shape[q][vertex[k]];
            const Tensor<1, dim> &grad = values.gradient[q][vertex[k]];
            const unsigned int    c    = component[k];
            phi_u[k]                   = Tensor<1, dim>();
            grad_u[k]                  = Tensor<2, dim>();
            phi_p[k]                   = 0;
            grad_p[k]                  = Tensor<1, dim>();
            if (c < dim)
              {
                phi_u[k][c]  = phi;
                grad_u[k][c] = grad;
              }
            else
              {
                phi_p[k]  = phi;
                grad_p[k] = grad;
              }
            eps_u[k] = symmetrize(grad_u[k]);
            div_u[k] = trace(grad_u[k]);
          }
        const double JxW = values.JxW[q];
        for (unsigned int i = 0; i < n_dofs; ++i)
          if (component[i] == dim)
            pressure_mass(i) += phi_p[i] * JxW / mu;
        Tensor<1, dim> forcing = rho / tau * u_star[q] + rho * gravity;
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
            // The geometric term 2 theta^2 k tau (grad u sigma*) : eps(v).
            const Tensor<2, dim> sigma(sigma_star[q]);
            for (unsigned int j = 0; j < n_dofs; ++j)
              if (component[j] < dim)
                stretching[j] = geometric_factor * grad_u[j] * sigma;
          }
        // Only the blocks that can be non-zero: this loop is most of
        // the assembly, in 3D especially.
        for (unsigned int i = 0; i < n_dofs; ++i)
          {
            const bool i_is_u = component[i] < dim;
            for (unsigned int j = 0; j < n_dofs; ++j)
              {
                const bool j_is_u = component[j] < dim;
                double     a_ij   = 0;
                if (i_is_u && j_is_u)
                  {
                    a_ij = (component[i] == component[j]
                              ? rho / tau * phi_u[i] * phi_u[j]
                              : 0.) +
                           2 * mu * eps_u[i] * eps_u[j];
                    if (with_stress)
                      a_ij += scalar_product(stretching[j], eps_u[i]);
                  }
                else if (i_is_u)
                  a_ij = -div_u[i] * phi_p[j];
                else if (j_is_u)
                  a_ij = -phi_p[i] * div_u[j] -
                         tau_K * rho / tau * phi_u[j] * grad_p[i];
                else
                  {
                    a_ij = -tau_K * grad_p[j] * grad_p[i];
                    schur(i, j) += schur_weight *
                                   (grad_p[i] * grad_p[j] +
                                    regularization * phi_p[i] * phi_p[j]) *
                                   JxW;
                  }
                matrix(i, j) += a_ij * JxW;
              }
            rhs(i) +=
              (forcing * phi_u[i] - tau_K * stabilized_forcing * grad_p[i]) *
              JxW;
            if (with_stress && i_is_u)
              rhs(i) -= explicit_stress * eps_u[i] * JxW;
          }
      }
    // The lumped pressure mass of the liquid part (with the whole cell's,
    // the mass of the staircase, the viscous regime took 1.6 times the
    // iterations on fine meshes: mu = 10 Pa s, L = 8, 25.6 against 16.5 per
    // step), but at least min_pressure_mass_fraction of the whole cell's:
    // a small cut must not make the preconditioner's M_p^-1 large.
    for (unsigned int i = 0; i < n_dofs; ++i)
      if (component[i] == dim)
        pressure_mass(i) =
          std::max(pressure_mass(i),
                   min_pressure_mass_fraction * cell->measure() /
                     cell->n_vertices() / mu);
    add_open_wall_terms(cell, h);
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
          parameters.wall_type[cell->face(f)->boundary_id()] == WallType::open)
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
    if (with_stress)
      {
        sigma_star.assign(n_q, SymmetricTensor<2, dim>());
        div_sigma_star.assign(n_q, Tensor<1, dim>());
      }
    if (with_explicit_strain)
      grad_u_star.assign(n_q, Tensor<2, dim>());
    for (const unsigned int v : transport_cell->vertex_indices())
      {
        Tensor<1, dim> u;
        for (unsigned int d = 0; d < dim; ++d)
          u[d] = fields.fields(transport_cell->vertex_dof_index(v, d));
        SymmetricTensor<2, dim> sigma;
        if (with_stress)
          for (unsigned int c = 0;
               c < TransportedFields<dim>::n_stress_components;
               ++c)
            sigma[SymmetricTensor<2, dim>::unrolled_to_component_indices(c)] =
              fields.fields(transport_cell->vertex_dof_index(
                v,
                TransportedFields<dim>::first_stress_component + c));
        for (unsigned int q = 0; q < n_q; ++q)
          {
            const double phi = values.shape[q][v];
            u_star[q] += phi * u;
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
  StokesCellSystem<dim>::add_surface_terms(
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    const double                                          h)
  {
    surface_values.reinit(cell, domain.cut_cell(cell).surface);
    const unsigned int n_dofs = matrix.m();
    const double       theta  = parameters.free_surface_stabilization;
    for (unsigned int q = 0; q < surface_values.size(); ++q)
      {
        const double          JxW    = surface_values.JxW[q];
        const Tensor<1, dim> &normal = surface_values.normal[q];
        const auto           &phi    = surface_values.shape[q];
        // The weight of the stabilisation: theta tau rho |g.n| where gravity
        // presses the surface back (g.n < 0, n pointing out of the liquid);
        // zero elsewhere, where the term would weaken the mass matrix.
        const double weight =
          theta * tau * parameters.density * std::max(-(gravity * normal), 0.);
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
