#include <vefs/stokes_cell_system.h>

namespace vefs
{
  template <int dim>
  StokesCellSystem<dim>::StokesCellSystem(const Parameters         &parameters,
                                          const Rheology<dim>      &rheology,
                                          const FiniteElement<dim> &flow_fe,
                                          const TransportedFields<dim> &fields,
                                          const double                  tau)
    : parameters(parameters)
    , rheology(rheology)
    , fields(fields)
    , tau(tau)
    , mu(rheology.effective_viscosity(tau))
    , kept(rheology.stress_factor(tau))
    , quadrature(2)
    , fe_values(flow_fe,
                quadrature,
                update_values | update_gradients | update_JxW_values)
    , advected(fields.mapping,
               fields.fe,
               quadrature,
               update_values | update_gradients)
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
    const unsigned int n_q    = quadrature.size();
    matrix.reinit(n_dofs, n_dofs);
    schur.reinit(n_dofs, n_dofs);
    rhs.reinit(n_dofs);
    pressure_mass.reinit(n_dofs);
    component.resize(n_dofs);
    for (unsigned int i = 0; i < n_dofs; ++i)
      component[i] = flow_fe.system_to_component_index(i).first;
    u_star.resize(n_q);
    sigma_star.resize(n_q);
    div_sigma_star.resize(n_q);
    stretching.resize(n_dofs);
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
    const FEValuesExtractors::Vector             velocity(0);
    const FEValuesExtractors::Scalar             pressure(dim);
    const FEValuesExtractors::SymmetricTensor<2> stress(
      TransportedFields<dim>::first_stress_component);
    const bool         with_stress = rheology.has_stress();
    const unsigned int n_dofs      = matrix.m();
    const double       rho         = parameters.density;

    fe_values.reinit(cell);
    advected.reinit(fields.cell_of(cell));
    advected[velocity].get_function_values(fields.fields, u_star);
    if (with_stress)
      {
        advected[stress].get_function_values(fields.fields, sigma_star);
        advected[stress].get_function_divergences(fields.fields,
                                                  div_sigma_star);
      }

    const double h = cell->minimum_vertex_distance();
    const double tau_K =
      parameters.pressure_stabilization / (rho / tau + 4 * mu / (h * h));
    schur_weight = tau / rho + tau_K;

    matrix        = 0;
    schur         = 0;
    rhs           = 0;
    pressure_mass = 0;
    for (const unsigned int q : fe_values.quadrature_point_indices())
      {
        for (unsigned int k = 0; k < n_dofs; ++k)
          {
            phi_u[k]  = fe_values[velocity].value(k, q);
            eps_u[k]  = fe_values[velocity].symmetric_gradient(k, q);
            div_u[k]  = fe_values[velocity].divergence(k, q);
            phi_p[k]  = fe_values[pressure].value(k, q);
            grad_p[k] = fe_values[pressure].gradient(k, q);
          }
        const double   JxW     = fe_values.JxW(q);
        Tensor<1, dim> forcing = rho / tau * u_star[q] + rho * gravity;
        // The explicit part of the stress, k div sigma* (k = kept), is a
        // force in the strong residual of the pressure stabilisation.
        Tensor<1, dim> stabilized_forcing = forcing;
        if (with_stress)
          {
            stabilized_forcing += kept * div_sigma_star[q];
            // The geometric term 2 k tau (grad u sigma*) : eps(v).
            const Tensor<2, dim> sigma(sigma_star[q]);
            for (unsigned int j = 0; j < n_dofs; ++j)
              if (component[j] < dim)
                stretching[j] =
                  2 * kept * tau * fe_values[velocity].gradient(j, q) * sigma;
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
              rhs(i) -= kept * sigma_star[q] * eps_u[i] * JxW;
            pressure_mass(i) += phi_p[i] / mu * JxW;
          }
      }
  }

  template class StokesCellSystem<2>;
  template class StokesCellSystem<3>;
} // namespace vefs
