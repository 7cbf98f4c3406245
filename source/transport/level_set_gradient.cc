#include <vefs/transport/level_set_gradient.h>

namespace vefs
{
  template <int dim>
  void
  LevelSetGradient<dim>::interpolate(const TransportedFields<dim> &fields,
                                     const Function<dim>          &level_set)
  {
    reinit(fields);
    const double step = 1e-6;
    for (const auto &node : fields.nodes())
      for (unsigned int d = 0; d < dim; ++d)
        {
          Point<dim> plus = node.point, minus = node.point;
          plus[d] += step;
          minus[d] -= step;
          gradient(node.dofs[d]) =
            (level_set.value(plus) - level_set.value(minus)) / (2 * step);
        }
    finalize(fields);
  }

  template class LevelSetGradient<2>;
  template class LevelSetGradient<3>;
} // namespace vefs
