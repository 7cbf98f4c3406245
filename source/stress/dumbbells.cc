#include <deal.II/base/mpi.h>

#include <vefs/base/errors.h>
#include <vefs/stress/dumbbells.h>
#include <vefs/stress/tensor_exponential.h>

#include <cmath>
#include <random>

namespace vefs
{
  namespace dumbbells
  {
    template <int dim>
    SymmetricTensor<2, dim>
    second_moment(const std::vector<Tensor<1, dim>> &q)
    {
      SymmetricTensor<2, dim> B;
      for (const auto &q_i : q)
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int b = a; b < dim; ++b)
            B[a][b] += q_i[a] * q_i[b];
      return B / static_cast<double>(q.size());
    }

    template <int dim>
    Tensor<2, dim>
    cholesky_factor(const SymmetricTensor<2, dim> &B)
    {
      Tensor<2, dim> L;
      for (unsigned int j = 0; j < dim; ++j)
        {
          double pivot = B[j][j];
          for (unsigned int k = 0; k < j; ++k)
            pivot -= L[j][k] * L[j][k];
          AssertThrow(pivot > 0,
                      ExcMessage("The second moment of the configuration "
                                 "fields is not positive definite."));
          L[j][j] = std::sqrt(pivot);
          for (unsigned int i = j + 1; i < dim; ++i)
            {
              double entry = B[i][j];
              for (unsigned int k = 0; k < j; ++k)
                entry -= L[i][k] * L[j][k];
              L[i][j] = entry / L[j][j];
            }
        }
      return L;
    }

    template <int dim>
    Tensor<2, dim>
    orthogonal_factor(const Tensor<2, dim> &A)
    {
      // Newton's iteration R <- (R + R^{-T}) / 2 converges quadratically to
      // the polar factor of a non-singular A.
      Tensor<2, dim> R = A;
      for (unsigned int iteration = 0; iteration < 100; ++iteration)
        {
          const Tensor<2, dim> next   = 0.5 * (R + transpose(invert(R)));
          const double         change = (next - R).norm();
          R                           = next;
          if (change <= 1e-15 * R.norm())
            break;
        }
      return R;
    }

    template <int dim>
    Tensor<2, dim>
    moment_map(const SymmetricTensor<2, dim> &B,
               const SymmetricTensor<2, dim> &B_new,
               const Tensor<2, dim>          &F)
    {
      const Tensor<2, dim> C = cholesky_factor(B);
      const Tensor<2, dim> D = cholesky_factor(B_new);
      const Tensor<2, dim> R = orthogonal_factor(invert(D) * F * C);
      return D * R * invert(C);
    }

    template <int dim>
    std::vector<Tensor<1, dim>>
    equilibrium_sample(const unsigned int n_fields, const unsigned int seed)
    {
      std::seed_seq                    sequence{seed};
      std::mt19937_64                  generator(sequence);
      std::normal_distribution<double> normal;
      std::vector<Tensor<1, dim>>      q(n_fields);
      for (auto &q_i : q)
        for (unsigned int d = 0; d < dim; ++d)
          q_i[d] = normal(generator);
      const Tensor<2, dim> to_identity =
        invert(cholesky_factor(second_moment(q)));
      for (auto &q_i : q)
        q_i = to_identity * q_i;
      return q;
    }

    template <int dim>
    std::vector<Tensor<1, dim>>
    increments(const unsigned int n_fields,
               const unsigned int seed,
               const unsigned int step)
    {
      std::seed_seq                    sequence{seed, step};
      std::mt19937_64                  generator(sequence);
      std::normal_distribution<double> normal;
      std::vector<Tensor<1, dim>>      xi(n_fields);
      for (auto &xi_i : xi)
        for (unsigned int d = 0; d < dim; ++d)
          xi_i[d] = normal(generator);
      return xi;
    }
  } // namespace dumbbells

  namespace
  {
    template <int dim>
    std::vector<Tensor<1, dim>>
    node_fields(const TransportedFields<dim>                &fields,
                const typename TransportedFields<dim>::Node &node)
    {
      std::vector<Tensor<1, dim>> q(fields.n_dumbbell_fields);
      for (unsigned int i = 0; i < q.size(); ++i)
        q[i] = fields.dumbbell(node, i);
      return q;
    }

    /**
     * sigma = G (<q q^T> - <p p^T>): the ensemble stress of one node's fields
     * @p q, with @p control the control variates' moment <p p^T> (I without
     * them).
     */
    template <int dim>
    SymmetricTensor<2, dim>
    ensemble_stress(const std::vector<Tensor<1, dim>> &q,
                    const SymmetricTensor<2, dim>     &control,
                    const double                       G)
    {
      return G * (dumbbells::second_moment(q) - control);
    }
  } // namespace

  template <int dim>
  SymmetricTensor<2, dim>
  control_moment(const TransportedFields<dim> &fields)
  {
    return fields.dumbbell_controls.empty()
             ? unit_symmetric_tensor<dim>()
             : dumbbells::second_moment(fields.dumbbell_controls);
  }

  template <int dim>
  void
  set_ensemble_stress(TransportedFields<dim> &fields,
                      const Rheology<dim>    &rheology)
  {
    const double                  G       = rheology.shear_modulus();
    const SymmetricTensor<2, dim> control = control_moment(fields);
    for (const auto &node : fields.nodes())
      fields.set_stress(node,
                        ensemble_stress(node_fields(fields, node), control, G));
    fields.finalize();
  }

  template <int dim>
  void
  match_dumbbells_to_stress(TransportedFields<dim> &fields,
                            const Rheology<dim>    &rheology)
  {
    const double                  G       = rheology.shear_modulus();
    const SymmetricTensor<2, dim> control = control_moment(fields);
    const SymmetricTensor<2, dim> control_offset =
      control - unit_symmetric_tensor<dim>();
    for (const auto &node : fields.nodes())
      {
        auto                          q = node_fields(fields, node);
        const SymmetricTensor<2, dim> target =
          rheology.conformation(fields.stress(node)) + control_offset;
        try
          {
            const Tensor<2, dim> T =
              dumbbells::moment_map<dim>(dumbbells::second_moment(q),
                                         target,
                                         Tensor<2, dim>(
                                           unit_symmetric_tensor<dim>()));
            for (unsigned int i = 0; i < q.size(); ++i)
              {
                q[i] = T * q[i];
                fields.set_dumbbell(node, i, q[i]);
              }
          }
        catch (const ExceptionBase &)
          {
            // Interpolation and extension take convex combinations, which
            // keep c positive definite; a node where it is not anyway (or
            // whose fields have collapsed) keeps its fields and takes their
            // stress.
          }
        // The stress of the fields just set, in the same pass.
        fields.set_stress(node, ensemble_stress(q, control, G));
      }
    fields.finalize();
  }

  template <int dim>
  void
  set_initial_dumbbells(TransportedFields<dim> &fields,
                        const Rheology<dim>    &rheology,
                        const unsigned int      seed,
                        const bool              variance_reduction)
  {
    const auto sample =
      dumbbells::equilibrium_sample<dim>(fields.n_dumbbell_fields, seed);
    fields.dumbbell_controls.clear();
    if (variance_reduction)
      fields.dumbbell_controls = sample;
    bool not_positive = false;
    for (const auto &node : fields.nodes())
      {
        const SymmetricTensor<2, dim> c0 =
          rheology.conformation(fields.stress(node));
        if (!(c0.norm() < std::numeric_limits<double>::max()) ||
            determinant(c0) <= 0 || trace(c0) <= 0)
          {
            not_positive = true;
            continue;
          }
        Tensor<2, dim> factor;
        try
          {
            factor = dumbbells::cholesky_factor(c0);
          }
        catch (const ExceptionBase &)
          {
            not_positive = true;
            continue;
          }
        for (unsigned int i = 0; i < sample.size(); ++i)
          fields.set_dumbbell(node, i, factor * sample[i]);
      }
    if (Utilities::MPI::logical_or(
          not_positive,
          fields.dof_handler.get_triangulation().get_communicator()))
      throw InputError("entry 'Initial liquid/Stress': I + sigma / G is not "
                       "positive definite somewhere in the cavity, so no "
                       "dumbbells have that stress ('Material/Stress model = "
                       "dumbbells')");
    fields.finalize();
    set_ensemble_stress(fields, rheology);
  }

  template <int dim>
  StressUpdateReport
  update_dumbbells(TransportedFields<dim>                            &fields,
                   const typename TransportedFields<dim>::VectorType &velocity,
                   const LiquidDomain<dim>                           &domain,
                   const Rheology<dim>                               &rheology,
                   const double                                       tau,
                   const std::vector<Tensor<1, dim>> &increments)
  {
    using VectorType = typename TransportedFields<dim>::VectorType;
    constexpr unsigned int first_moment =
      TransportedFields<dim>::first_stress_component;
    const unsigned int first_map = fields.first_dumbbell_component;
    // N_f >= dim leaves room for the dim^2 entries of E.
    Assert(fields.n_dumbbell_fields >= dim, ExcInternalError());

    // Over the liquid cells around each node: the cell volume (component
    // 0), the volume-weighted E (the slots of the first fields) and
    // E <q* q*^T> E^T (the stress slots).
    VectorType sum;
    fields.initialize_vector(sum);
    // The stress components hold G (<q* q*^T> - <p p^T>) (set_ensemble_
    // stress()): <q* q*^T> is their conformation plus this.
    const SymmetricTensor<2, dim> control_offset =
      control_moment(fields) - unit_symmetric_tensor<dim>();
    const StressUpdateReport report = for_each_liquid_vertex<dim>(
      fields,
      velocity,
      domain,
      rheology,
      tau,
      [&](const auto &cell, const unsigned int v, const Tensor<2, dim> &L) {
        const Tensor<2, dim> E =
          tensor_exponential(rheology.limited_strain(L, tau));
        // <q* q*^T> at the vertex is c* of the stress the fields hold
        // (set_ensemble_stress() before the flow step): no loop over them
        // for every cell around the vertex.
        const Tensor<2, dim> c(
          rheology.conformation(fields.stress_at(cell, v)) + control_offset);
        const SymmetricTensor<2, dim> carried =
          symmetrize(E * c * transpose(E));
        const double weight = cell->measure();
        fields.entry_at(sum, cell, v, 0) += weight;
        for (unsigned int k = 0; k < dim * dim; ++k)
          fields.entry_at(sum, cell, v, first_map + k) +=
            weight * E[k / dim][k % dim];
        for (unsigned int k = 0;
             k < TransportedFields<dim>::n_stress_components;
             ++k)
          fields.entry_at(sum, cell, v, first_moment + k) +=
            weight * carried.access_raw_entry(k);
      });
    sum.compress(VectorOperation::add);

    const double k     = rheology.stress_factor(tau);
    const double keep  = std::sqrt(k);
    const double noise = std::sqrt(1 - k);
    for (const auto &node : fields.nodes())
      {
        const double weight = sum(node.dofs[0]);
        if (!(weight > 0))
          continue;
        Tensor<2, dim>          E_mean;
        SymmetricTensor<2, dim> carried;
        for (unsigned int c = 0; c < dim * dim; ++c)
          E_mean[c / dim][c % dim] = sum(node.dofs[first_map + c]) / weight;
        for (unsigned int c = 0;
             c < TransportedFields<dim>::n_stress_components;
             ++c)
          carried.access_raw_entry(c) =
            sum(node.dofs[first_moment + c]) / weight;
        const auto           q_star = node_fields(fields, node);
        const Tensor<2, dim> T =
          dumbbells::moment_map(dumbbells::second_moment(q_star),
                                carried,
                                E_mean);
        for (unsigned int i = 0; i < q_star.size(); ++i)
          fields.set_dumbbell(node,
                              i,
                              keep * (T * q_star[i]) + noise * increments[i]);
      }
    for (unsigned int i = 0; i < fields.dumbbell_controls.size(); ++i)
      fields.dumbbell_controls[i] =
        keep * fields.dumbbell_controls[i] + noise * increments[i];
    fields.finalize();
    set_ensemble_stress(fields, rheology);
    return report;
  }

#define VEFS_INSTANTIATE(dim)                                              \
  template void match_dumbbells_to_stress<dim>(TransportedFields<dim> &,   \
                                               const Rheology<dim> &);     \
  template SymmetricTensor<2, dim> dumbbells::second_moment<dim>(          \
    const std::vector<Tensor<1, dim>> &);                                  \
  template Tensor<2, dim> dumbbells::cholesky_factor<dim>(                 \
    const SymmetricTensor<2, dim> &);                                      \
  template Tensor<2, dim> dumbbells::orthogonal_factor<dim>(               \
    const Tensor<2, dim> &);                                               \
  template Tensor<2, dim> dumbbells::moment_map<dim>(                      \
    const SymmetricTensor<2, dim> &,                                       \
    const SymmetricTensor<2, dim> &,                                       \
    const Tensor<2, dim> &);                                               \
  template std::vector<Tensor<1, dim>> dumbbells::equilibrium_sample<dim>( \
    const unsigned int,                                                    \
    const unsigned int);                                                   \
  template std::vector<Tensor<1, dim>> dumbbells::increments<dim>(         \
    const unsigned int,                                                    \
    const unsigned int,                                                    \
    const unsigned int);                                                   \
  template SymmetricTensor<2, dim> control_moment<dim>(                    \
    const TransportedFields<dim> &);                                       \
  template void set_ensemble_stress<dim>(TransportedFields<dim> &,         \
                                         const Rheology<dim> &);           \
  template void set_initial_dumbbells<dim>(TransportedFields<dim> &,       \
                                           const Rheology<dim> &,          \
                                           const unsigned int,             \
                                           const bool);                    \
  template StressUpdateReport update_dumbbells<dim>(                       \
    TransportedFields<dim> &,                                              \
    const typename TransportedFields<dim>::VectorType &,                   \
    const LiquidDomain<dim> &,                                             \
    const Rheology<dim> &,                                                 \
    const double,                                                          \
    const std::vector<Tensor<1, dim>> &);

  VEFS_INSTANTIATE(2)
  VEFS_INSTANTIATE(3)
#undef VEFS_INSTANTIATE
} // namespace vefs
