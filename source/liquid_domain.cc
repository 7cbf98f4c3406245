#include <vefs/free_surface.h>
#include <vefs/liquid_domain.h>

namespace vefs
{
  template <int dim>
  LiquidDomain<dim>::LiquidDomain(const TransportedFields<dim> &fields)
    : fraction(liquid_fractions(fields))
    , locations(fraction.size(), Location::empty)
  {
    for (const auto &cell :
         fields.dof_handler.get_triangulation().active_cell_iterators())
      if (!cell->is_artificial() &&
          is_liquid(fraction[cell->active_cell_index()]))
        locations[cell->active_cell_index()] = Location::full;
  }

  template class LiquidDomain<2>;
  template class LiquidDomain<3>;
} // namespace vefs
