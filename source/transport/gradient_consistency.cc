#include <deal.II/base/mpi.h>

#include <vefs/transport/field_hermite.h>
#include <vefs/transport/gradient_consistency.h>

#include <algorithm>

namespace vefs
{
  template <int dim>
  types::global_dof_index
  hold_gradient_to_values(const TransportedFields<dim> &fields,
                          LevelSetGradient<dim>        &level_set_gradient,
                          const double                  bound)
  {
    FieldHermite<dim> from_values;
    from_values.recover(fields);
    types::global_dof_index changed = 0;
    for (const auto &node : fields.nodes())
      {
        const Tensor<1, dim> r = from_values.nodal_gradient(node);
        if ((level_set_gradient.at(node) - r).norm() >
            bound * std::max(1., r.norm()))
          {
            level_set_gradient.set(node, r);
            ++changed;
          }
      }
    level_set_gradient.finalize(fields);
    return Utilities::MPI::sum(
      changed,
      fields.dof_handler.get_triangulation().get_communicator());
  }

  template types::global_dof_index
  hold_gradient_to_values(const TransportedFields<2> &,
                          LevelSetGradient<2> &,
                          const double);
  template types::global_dof_index
  hold_gradient_to_values(const TransportedFields<3> &,
                          LevelSetGradient<3> &,
                          const double);
} // namespace vefs
