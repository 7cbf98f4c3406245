#ifndef vefs_dumbbells_h
#define vefs_dumbbells_h

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <vefs/fields/transported_fields.h>
#include <vefs/stress/rheology.h>
#include <vefs/stress/stress.h>
#include <vefs/transport/liquid_domain.h>

#include <vector>

namespace vefs
{
  /**
   * Hookean dumbbells as Brownian configuration fields (doc/dumbbells.md):
   * N_f vector fields q_i carried by the flow, each driven by one Wiener
   * process for the whole domain, with the ensemble stress
   * sigma = G (<q q^T> - I), G = eta_p / lambda, <.> the mean over the
   * fields. The pieces below act at one point; the functions after the
   * namespace apply them to the transported fields.
   */
  namespace dumbbells
  {
    /** <q q^T>: the mean of q_i q_i^T over the fields. */
    template <int dim>
    SymmetricTensor<2, dim>
    second_moment(const std::vector<Tensor<1, dim>> &q);

    /**
     * The lower triangular L with L L^T = @p B; throws ExcMessage if @p B
     * is not positive definite.
     */
    template <int dim>
    Tensor<2, dim>
    cholesky_factor(const SymmetricTensor<2, dim> &B);

    /** The orthogonal factor R of the polar decomposition A = R U. */
    template <int dim>
    Tensor<2, dim>
    orthogonal_factor(const Tensor<2, dim> &A);

    /**
     * The linear map T nearest to @p F with T B T^T = @p B_new: T =
     * D R C^{-1} with C C^T = B, D D^T = B_new and R the orthogonal matrix
     * nearest to D^{-1} F C. If F B F^T = B_new, then T = F.
     */
    template <int dim>
    Tensor<2, dim>
    moment_map(const SymmetricTensor<2, dim> &B,
               const SymmetricTensor<2, dim> &B_new,
               const Tensor<2, dim>          &F);

    /**
     * @p n_fields vectors whose second moment is exactly the identity:
     * standard normal draws (seeded by @p seed) mapped by the inverse
     * Cholesky factor of their own second moment.
     */
    template <int dim>
    std::vector<Tensor<1, dim>>
    equilibrium_sample(const unsigned int n_fields, const unsigned int seed);

    /**
     * The standard normal increments xi_i of step @p step, one per field:
     * the same on every rank, and a function of (seed, step) only, so that
     * a resumed run draws what the uninterrupted one drew.
     */
    template <int dim>
    std::vector<Tensor<1, dim>>
    increments(const unsigned int n_fields,
               const unsigned int seed,
               const unsigned int step);
  } // namespace dumbbells

  /**
   * The fields at the start of a run: q_i(x) = chol(c_0(x)) q^_i, q^ an
   * equilibrium_sample() and c_0 = I + sigma_0 / G from the initial stress
   * the fields hold, so that <q q^T> = c_0 exactly; with
   * @p variance_reduction the equilibrium fields p_i = q^_i
   * (TransportedFields::dumbbell_controls, <p p^T> = I exactly); then the
   * ensemble stress. Throws InputError naming 'Initial liquid/Stress' where
   * c_0 is not positive definite.
   */
  template <int dim>
  void
  set_initial_dumbbells(TransportedFields<dim> &fields,
                        const Rheology<dim>    &rheology,
                        const unsigned int      seed,
                        const bool              variance_reduction);

  /**
   * <p p^T> of the equilibrium fields (TransportedFields::dumbbell_controls),
   * the identity without them: what the ensemble stress subtracts.
   */
  template <int dim>
  SymmetricTensor<2, dim>
  control_moment(const TransportedFields<dim> &fields);

  /**
   * The stress components of the fields := G (<q q^T> - control_moment())
   * at every node.
   */
  template <int dim>
  void
  set_ensemble_stress(TransportedFields<dim> &fields,
                      const Rheology<dim>    &rheology);

  /**
   * After an interpolation of the fields q_i and the stress apart: maps the
   * fields at each node by the moment_map() T nearest to the identity with
   * <(T q) (T q)^T> = c + control_moment() - I, c the conformation of the
   * node's stress, and then sets the ensemble stress. The interpolated <q q^T>
   * is smaller than the interpolated c (a Jensen gap, O(1) where the fields
   * vary across a cell, as at a moving contact line); the stress carries what
   * the macroscopic run carries (doc/dumbbells.md, "Interpolation"). A node
   * whose c + control_moment() - I is not positive definite keeps its fields
   * and takes their stress.
   */
  template <int dim>
  void
  match_dumbbells_to_stress(TransportedFields<dim> &fields,
                            const Rheology<dim>    &rheology);

  /**
   * The dumbbells' step 9 of doc/time_step_flow.md (doc/dumbbells.md):
   * each liquid cell around a node carries its fields by E = exp(tau L)
   * (the macroscopic exponential update's L, strain bound included), and
   * the node's fields become q_i = sqrt(k) T q*_i + sqrt(1 - k) xi_i, k the
   * stress factor of the step, xi_i = @p increments, T the moment_map() from
   * <q* q*^T> to the cells' weighted mean of E <q* q*^T> E^T, nearest to
   * their mean E. The mean of <q q^T> over the increments is then the
   * macroscopic update's c; with alpha = 0 (k = 1) it is that c. The
   * equilibrium fields, if any, take the same increments without a flow:
   * p_i = sqrt(k) p_i + sqrt(1 - k) xi_i. Then the ensemble stress. The
   * stress components must hold the fields' ensemble stress on entry
   * (set_ensemble_stress()). Returns what update_stress() returns.
   */
  template <int dim>
  StressUpdateReport
  update_dumbbells(TransportedFields<dim>                            &fields,
                   const typename TransportedFields<dim>::VectorType &velocity,
                   const LiquidDomain<dim>                           &domain,
                   const Rheology<dim>                               &rheology,
                   const double                                       tau,
                   const std::vector<Tensor<1, dim>> &increments);
} // namespace vefs

#endif
