#include <vefs/transport/characteristics.h>
#include <vefs/transport/level_set_history.h>
#include <vefs/transport/nodal_gradients.h>

#include <algorithm>
#include <cmath>

namespace vefs
{
  namespace
  {
    /**
     * Lends @p vector to @p holder (the fields, or the level set gradient)
     * for as long as it lives, so that the holder's own interpolation reads
     * it: the kept vectors have the fields' layout, on the same mesh.
     */
    template <typename Holder>
    class Lent
    {
    public:
      using VectorType = typename Holder::VectorType;

      Lent(Holder &holder, VectorType &vector)
        : holder(holder)
        , vector(vector)
      {
        holder.swap(vector);
      }

      ~Lent()
      {
        holder.swap(vector);
      }

    private:
      Holder     &holder;
      VectorType &vector;
    };
  } // namespace

  template <int dim>
  LevelSetHistory<dim>::LevelSetHistory(const double remap_distance)
    : remap_distance(remap_distance)
  {
  }

  template <int dim>
  void
  LevelSetHistory<dim>::add_step(const TransportedFields<dim> &fields,
                                 const double                  tau)
  {
    if (!has_base)
      return;
    Step step;
    fields.copy_to(step.velocity);
    step.velocity_gradient = recover_nodal_gradients(fields, dim);
    step.tau               = tau;
    steps.push_back(std::move(step));
  }

  template <int dim>
  void
  LevelSetHistory<dim>::compose(TransportedFields<dim>     &fields,
                                LevelSetGradient<dim>      &level_set_gradient,
                                const BoxMeshLocator<dim>  &locator,
                                const LevelSetInterpolation interpolation)
  {
    if (!has_base)
      return;
    const bool gradient_augmented =
      interpolation == LevelSetInterpolation::gradient_augmented;
    const auto &nodes = fields.nodes();

    std::vector<Point<dim>>     points(nodes.size());
    std::vector<Tensor<2, dim>> jacobians(nodes.size(),
                                          unit_symmetric_tensor<dim>());
    std::vector<double>         beyond_contact(nodes.size(), 0.);
    for (unsigned int i = 0; i < nodes.size(); ++i)
      points[i] = nodes[i].point;
    for (auto step = steps.rbegin(); step != steps.rend(); ++step)
      {
        const Lent<TransportedFields<dim>> velocity(fields, step->velocity);
        trace_back<dim>(fields,
                        step->velocity_gradient,
                        step->tau,
                        locator,
                        points,
                        gradient_augmented ? &jacobians : nullptr,
                        beyond_contact);
      }

    std::vector<std::pair<double, Tensor<1, dim>>> at_feet;
    {
      const Lent<TransportedFields<dim>> level_set(fields, base_level_set);
      const Lent<LevelSetGradient<dim>>  gradient(level_set_gradient,
                                                 base_gradient);
      at_feet = level_set_at<dim>(fields,
                                  level_set_gradient,
                                  points,
                                  locator,
                                  interpolation);
    }

    for (unsigned int i = 0; i < nodes.size(); ++i)
      {
        // Liquid that left a contact wall left empty space behind.
        fields.set_level_set(nodes[i],
                             beyond_contact[i] > 0
                               ? std::max(at_feet[i].first, beyond_contact[i])
                               : at_feet[i].first);
        // grad psi^n(x) = J^T grad psi^m(X(x)).
        if (gradient_augmented)
          level_set_gradient.set(nodes[i], at_feet[i].second * jacobians[i]);
      }
    fields.finalize();
    if (gradient_augmented)
      level_set_gradient.finalize(fields);
  }

  template <int dim>
  bool
  LevelSetHistory<dim>::remap_due(const double cfl, const double next_cfl)
  {
    moved += cfl;
    // Each step traces back through all kept steps: at most twice the
    // remap distance (in cells) of them, so that slow phases (a flow that
    // stops and reverses) do not make the steps ever longer. (Vortex at
    // h = 1/128, CFL 1, R = 10: L1 4.0e-4 unbounded, 4.3e-4 with 2R,
    // 5.6e-4 with R; the 3D deformation stalled at 40 s per step.)
    const std::size_t max_steps =
      std::max<std::size_t>(1, std::ceil(2 * remap_distance));
    return !has_base || moved + next_cfl > remap_distance ||
           steps.size() >= max_steps;
  }

  template <int dim>
  void
  LevelSetHistory<dim>::remap(const TransportedFields<dim> &fields,
                              const LevelSetGradient<dim>  &level_set_gradient)
  {
    if (!enabled())
      return;
    fields.copy_to(base_level_set);
    level_set_gradient.copy_to(base_gradient, fields);
    steps.clear();
    moved    = 0;
    has_base = true;
  }

  template <int dim>
  void
  LevelSetHistory<dim>::shift_base(TransportedFields<dim> &fields,
                                   const double            shift)
  {
    if (!has_base)
      return;
    const Lent<TransportedFields<dim>> level_set(fields, base_level_set);
    for (const auto &node : fields.nodes())
      fields.set_level_set(node, fields.level_set(node) + shift);
    fields.finalize();
  }

  template <int dim>
  typename LevelSetHistory<dim>::Scalars
  LevelSetHistory<dim>::scalars() const
  {
    Scalars result{has_base, moved, {}};
    for (const Step &step : steps)
      result.taus.push_back(step.tau);
    return result;
  }

  template <int dim>
  std::vector<const typename TransportedFields<dim>::VectorType *>
  LevelSetHistory<dim>::vectors() const
  {
    std::vector<const VectorType *> result;
    if (!has_base)
      return result;
    result = {&base_level_set, &base_gradient};
    for (const Step &step : steps)
      {
        result.push_back(&step.velocity);
        for (const VectorType &component : step.velocity_gradient)
          result.push_back(&component);
      }
    return result;
  }

  template <int dim>
  std::vector<typename TransportedFields<dim>::VectorType *>
  LevelSetHistory<dim>::restore(const Scalars                &scalars,
                                const TransportedFields<dim> &fields)
  {
    has_base = scalars.has_base;
    moved    = scalars.moved;
    steps.clear();
    std::vector<VectorType *> result;
    if (!has_base)
      return result;
    result = {&base_level_set, &base_gradient};
    for (const double tau : scalars.taus)
      {
        steps.emplace_back();
        steps.back().tau = tau;
        result.push_back(&steps.back().velocity);
        for (VectorType &component : steps.back().velocity_gradient)
          result.push_back(&component);
      }
    for (VectorType *vector : result)
      {
        fields.initialize_vector(*vector);
        vector->zero_out_ghost_values();
      }
    return result;
  }

  template <int dim>
  void
  LevelSetHistory<dim>::restored()
  {
    if (!has_base)
      return;
    base_level_set.update_ghost_values();
    base_gradient.update_ghost_values();
    for (Step &step : steps)
      {
        step.velocity.update_ghost_values();
        for (VectorType &component : step.velocity_gradient)
          component.update_ghost_values();
      }
  }

  template class LevelSetHistory<2>;
  template class LevelSetHistory<3>;
} // namespace vefs
