#ifndef vefs_rheology_h
#define vefs_rheology_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <vefs/stress/tensor_exponential.h>

#include <cmath>
#include <vector>

namespace vefs
{
  using namespace dealii;

  /** The regime selected by the material parameters (doc/method.md,
   * "Equations"). */
  enum class Regime
  {
    newtonian,
    oldroyd_b,
    elastic_solid
  };

  /**
   * How the stress is advanced by the velocity gradient of the step, after
   * the diffusion step (doc/time_step_flow.md, step 9).
   */
  enum class StressUpdate
  {
    /** Resolved by the material's regime: StressParameters::resolve(). */
    automatic,
    linear,
    exponential
  };

  /**
   * How the updated stress reaches the nodes, where the characteristics
   * read it: update_stress().
   */
  enum class NodalStress
  {
    /** Resolved by StressParameters::resolve_nodal_stress(). */
    automatic,
    /** Each liquid cell updates its vertices, the node takes the mean. */
    vertex_average,
    /** The update's increment at the liquid's quadrature points, lumped. */
    lumped_increment
  };

  /**
   * What carries the polymer stress (doc/dumbbells.md): the constitutive
   * law itself, or an ensemble of Hookean dumbbells as Brownian
   * configuration fields.
   */
  enum class StressModel
  {
    macroscopic,
    dumbbells
  };

  /**
   * The material and the body force on it: subsection "Material" and the
   * top-level entry "Gravity". The defaults: water under the earth's
   * gravity.
   */
  struct MaterialParameters
  {
    void
    declare(dealii::ParameterHandler &prm);

    /** Throws InputError for a material that no regime describes. */
    void
    check(const unsigned int dimension) const;

    Regime
    regime() const
    {
      if (relaxation_time == 0)
        return Regime::newtonian;
      return alpha == 1 ? Regime::oldroyd_b : Regime::elastic_solid;
    }

    /** Effective viscosity of the Newtonian regime. */
    double
    newtonian_viscosity() const
    {
      return solvent_viscosity + polymer_viscosity;
    }

    bool
    has_dumbbells() const
    {
      return stress_model == StressModel::dumbbells;
    }

    /** G = eta_p / lambda, with a stress (not the Newtonian regime). */
    double
    shear_modulus() const
    {
      return polymer_viscosity / relaxation_time;
    }

    double              density           = 1000;
    double              solvent_viscosity = 0.001;
    double              polymer_viscosity = 0;
    double              relaxation_time   = 0;
    double              alpha             = 1;
    std::vector<double> gravity           = {0, -9.81};
    StressModel         stress_model      = StressModel::macroscopic;
    /** N_f, the number of configuration fields. */
    unsigned int dumbbell_fields = 100;
    /** Seed of the fields' initial vectors and Wiener increments. */
    unsigned int dumbbell_seed = 1;
    /**
     * Whether the ensemble stress subtracts that of equilibrium fields
     * driven by the same increments (doc/dumbbells.md, "Variance
     * reduction").
     */
    bool dumbbell_variance_reduction = true;
  };

  /** How the stress is updated after the flow step: subsection "Stress". */
  struct StressParameters
  {
    void
    declare(dealii::ParameterHandler &prm);

    /**
     * 'automatic' becomes exponential: an impact breaks the linear update
     * of an elastic solid (doc/time_step_flow.md, step 9), large steps that
     * of an Oldroyd-B liquid (doc/viscoelastic.md, "Positivity"), and the
     * dumbbells' update is the exponential one (doc/dumbbells.md).
     */
    void
    resolve();

    /**
     * 'Nodal stress' automatic becomes the lumped increment for an elastic
     * solid that holds its shape under its weight (@p stiff_solid), whose
     * impacts lose less energy by it, and the vertex average otherwise: a
     * soft solid's sheets a few cells thick lose more by the lumping
     * (doc/bouncing_ball.md, "Energy budget"), and a liquid's relaxation
     * would be smoothed as well.
     */
    void
    resolve_nodal_stress(const bool stiff_solid);

    StressUpdate stress_update = StressUpdate::automatic;
    /** Weight of the new velocity in the stress of the diffusion step. */
    double      stress_theta = 1;
    NodalStress nodal_stress = NodalStress::automatic;
  };

  /**
   * The constitutive law of doc/method.md ("Equations") as the diffusion
   * step sees it at one point, once sigma is eliminated (doc/time_step_flow.md,
   * "The stress in the Stokes step"):
   *   sigma^{n+1}(u) = k [sigma* + tau (grad u sigma* + sigma* grad u^T)
   *                       + tau (2 eta_p / lambda) eps(u)],
   *   k = lambda / (lambda + alpha tau),
   * with sigma* the advected stress. The momentum equation then has the
   * effective viscosity mu = eta_s + tau eta_p / (lambda + alpha tau), the
   * geometric term 2 k tau (grad u sigma*) : eps(v) and the right-hand side
   * -k sigma* : eps(v). A Newtonian liquid has no stress: mu = eta_s + eta_p.
   *
   * With 'Stress theta' = theta < 1 the stress law sees the velocity
   * u_theta = theta u + (1 - theta) u*, and the momentum equation the stress
   * theta sigma^{n+1}(u) + (1 - theta) sigma*. For theta = 1/2 this is the
   * midpoint rule, which keeps the energy of a linear elastic oscillation
   * that the seed's backward Euler (theta = 1) damps. Written out, the
   * momentum stress is
   *   explicit_stress_factor sigma* + theta^2 k tau S(u) + theta (1 - theta)
   *   k tau S(u*),   S(u) = grad u sigma* + sigma* grad u^T + 2 G eps(u),
   * so the effective viscosity and the geometric term carry theta^2.
   *
   * The second-order scheme (doc/time_step_flow.md) averages the old and
   * new forces in the momentum equation itself, the old ones through the
   * carried acceleration: its momentum stress is the whole sigma^{n+1} of
   * the midpoint velocity (momentum weight m = 1, theta = 1/2). In general
   *   (m k + 1 - m) sigma* + m theta k tau S(u) + m (1 - theta) k tau S(u*),
   * and m = theta for the first-order scheme. Its relaxation (alpha > 0) is
   * integrated exactly for a constant source over the step instead of by
   * backward Euler: sigma* decays by k_s = exp(-x), x = alpha tau / lambda,
   * and the new terms carry k = (1 - exp(-x)) / x (both 1 for a solid);
   * the first-order scheme has k_s = k = lambda / (lambda + alpha tau).
   */
  template <int dim>
  class Rheology
  {
  public:
    /**
     * @p max_strain: 'Time/Maximum strain per step' (0: none);
     * @p second_order: 'Time/Scheme = second order'.
     */
    Rheology(const MaterialParameters &material,
             const StressParameters   &stress,
             const double              max_strain,
             const bool                second_order = false)
      : regime(material.regime())
      , eta_s(material.solvent_viscosity)
      , eta_p(material.polymer_viscosity)
      , lambda(material.relaxation_time)
      , alpha(material.alpha)
      , update(stress.stress_update)
      , max_strain(max_strain)
      , theta(second_order ? 0.5 : stress.stress_theta)
      , momentum_weight(second_order ? 1. : stress.stress_theta)
      , exponential_relaxation(second_order)
    {
      Assert(update != StressUpdate::automatic,
             dealii::ExcMessage("StressParameters::resolve() first."));
    }

    /** Oldroyd-B liquids and elastic solids carry a stress field. */
    bool
    has_stress() const
    {
      return regime != Regime::newtonian;
    }

    /** G = eta_p / lambda, the elastic modulus of the stress. */
    double
    shear_modulus() const
    {
      return eta_p / lambda;
    }

    double
    effective_viscosity(const double tau) const
    {
      if (!has_stress())
        return eta_s + eta_p;
      if (exponential_relaxation)
        return eta_s + momentum_weight * theta * stress_factor(tau) * tau *
                         eta_p / lambda;
      return eta_s +
             momentum_weight * theta * tau * eta_p / (lambda + alpha * tau);
    }

    /** k: the factor of what the step adds to the advected stress. */
    double
    stress_factor(const double tau) const
    {
      if (!has_stress())
        return 0.;
      if (exponential_relaxation)
        {
          const double x = alpha * tau / lambda;
          return x > 0 ? -std::expm1(-x) / x : 1.;
        }
      return lambda / (lambda + alpha * tau);
    }

    /** k_s: how much of the advected stress survives the step. */
    double
    relaxation_factor(const double tau) const
    {
      if (exponential_relaxation && has_stress())
        return std::exp(-alpha * tau / lambda);
      return stress_factor(tau);
    }

    /** The weight theta of the new velocity in the stress law. */
    double
    implicit_weight() const
    {
      return theta;
    }

    /** The factor of sigma* in the momentum stress: m k_s + 1 - m. */
    double
    explicit_stress_factor(const double tau) const
    {
      return has_stress()
               ? momentum_weight * relaxation_factor(tau) + 1 - momentum_weight
               : 0.;
    }

    /** The factor 2 m theta k tau of the geometric term (grad u sigma*). */
    double
    geometric_factor(const double tau) const
    {
      return 2 * momentum_weight * theta * stress_factor(tau) * tau;
    }

    /**
     * The explicit part m (1 - theta) k tau S(u*) of the momentum stress,
     * zero for theta = 1.
     */
    SymmetricTensor<2, dim>
    explicit_strain_stress(const SymmetricTensor<2, dim> &advected,
                           const Tensor<2, dim>          &grad_u_star,
                           const double                   tau) const
    {
      const Tensor<2, dim> stretching = grad_u_star * advected;
      return momentum_weight * (1 - theta) * stress_factor(tau) * tau *
             (symmetrize(stretching + transpose(stretching)) +
              2 * shear_modulus() * symmetrize(grad_u_star));
    }

    /**
     * sigma^{n+1} from the advected stress and the new velocity gradient L.
     * With c = I + sigma / G (G = eta_p / lambda), both updates carry c* by
     * L, then relax: c^{n+1} = I + k (c' - I). Linear: c' = c* + tau (L c*
     * + c* L^T), the formula the diffusion step sees. Exponential: c' =
     * exp(tau L) c* exp(tau L)^T, positive definite whatever tau |L| is,
     * with the strain tau L limited to 'Maximum strain per step' (if set).
     */
    SymmetricTensor<2, dim>
    updated_stress(const SymmetricTensor<2, dim> &advected,
                   const Tensor<2, dim>          &grad_u,
                   const double                   tau) const
    {
      if (update == StressUpdate::exponential)
        {
          const Tensor<2, dim> E =
            tensor_exponential(limited_strain(grad_u, tau));
          const Tensor<2, dim> carried =
            E * Tensor<2, dim>(conformation(advected)) * transpose(E);
          if (exponential_relaxation)
            // The advected part decays by k_s, what the step carried in by
            // k, as in the linear formula.
            return relaxation_factor(tau) * advected +
                   stress_factor(tau) * shear_modulus() *
                     (symmetrize(carried) - conformation(advected));
          return stress_factor(tau) * shear_modulus() *
                 (symmetrize(carried) - unit_symmetric_tensor<dim>());
        }
      const Tensor<2, dim> stretching = grad_u * advected;
      if (exponential_relaxation)
        return relaxation_factor(tau) * advected +
               stress_factor(tau) *
                 (tau * symmetrize(stretching + transpose(stretching)) +
                  (tau * 2 * eta_p / lambda) * symmetrize(grad_u));
      return stress_factor(tau) *
             (advected + tau * symmetrize(stretching + transpose(stretching)) +
              (tau * 2 * eta_p / lambda) * symmetrize(grad_u));
    }

    /**
     * The conformation tensor c = I + lambda sigma / eta_p (Oldroyd-B), or
     * the left Cauchy-Green tensor B = I + sigma / G with G = eta_p / lambda
     * (elastic solid): the same expression. Positive definite in the exact
     * solution.
     */
    SymmetricTensor<2, dim>
    conformation(const SymmetricTensor<2, dim> &sigma) const
    {
      return unit_symmetric_tensor<dim>() + (lambda / eta_p) * sigma;
    }

    /**
     * Elastic (free) energy density G/2 (tr c - d - ln det c), G =
     * eta_p / lambda: the free energy of the Oldroyd-B dumbbells, and for
     * the incompressible neo-Hookean solid (det B = 1) its strain energy
     * G/2 (tr B - d). It is non-negative for a positive definite c; where c
     * is not, the logarithm is dropped (those points are counted apart).
     */
    double
    elastic_energy_density(const SymmetricTensor<2, dim> &sigma) const
    {
      const SymmetricTensor<2, dim> c = conformation(sigma);
      const double                  J = determinant(c);
      return 0.5 * shear_modulus() *
             (trace(c) - dim - (J > 0 ? std::log(J) : 0.));
    }

    /**
     * The strain tau L of the exponential update, scaled down to the norm
     * 'Maximum strain per step' where it is larger. The time step keeps it
     * below that bound, except in a step it could not foresee, an impact:
     * there the limiter stretches the stress less than the velocity would,
     * which stores less elastic energy, where the unlimited exponential
     * would store e^(2 tau |L|) times the stress and inject energy.
     */
    Tensor<2, dim>
    limited_strain(const Tensor<2, dim> &grad_u, const double tau) const
    {
      const Tensor<2, dim> strain = tau * grad_u;
      const double         norm   = strain.norm();
      return is_strain_limited(grad_u, tau) ? (max_strain / norm) * strain
                                            : strain;
    }

    /** Whether limited_strain() scales the strain of this step down. */
    bool
    is_strain_limited(const Tensor<2, dim> &grad_u, const double tau) const
    {
      return update == StressUpdate::exponential && max_strain > 0 &&
             tau * grad_u.norm() > max_strain;
    }

  private:
    const Regime       regime;
    const double       eta_s, eta_p, lambda, alpha;
    const StressUpdate update;
    const double       max_strain;
    /** The weight theta of the new velocity in the stress law. */
    const double theta;
    /** The weight m of sigma^{n+1} in the momentum equation. */
    const double momentum_weight;
    /** The second-order scheme's relaxation factors (k_s = exp(-x)). */
    const bool exponential_relaxation;
  };
} // namespace vefs

#endif
