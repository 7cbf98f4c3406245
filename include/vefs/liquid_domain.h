#ifndef vefs_liquid_domain_h
#define vefs_liquid_domain_h

#include <deal.II/lac/vector.h>

#include <vefs/transported_fields.h>

namespace vefs
{
  /**
   * The liquid as the flow step sees it on the current mesh: which cells
   * hold liquid, and the liquid fraction of every owned and ghost cell (for
   * the pictures and the load balance).
   */
  template <int dim>
  class LiquidDomain
  {
  public:
    using CellIterator = typename Triangulation<dim>::active_cell_iterator;

    /** Where a cell lies with respect to the liquid. */
    enum class Location
    {
      empty,
      full
    };

    /** Classify the owned and ghost cells of the mesh of @p fields. */
    explicit LiquidDomain(const TransportedFields<dim> &fields);

    Location
    location(const CellIterator &cell) const
    {
      return locations[cell->active_cell_index()];
    }

    bool
    has_liquid(const CellIterator &cell) const
    {
      return location(cell) != Location::empty;
    }

    /** Liquid fraction of every owned and ghost cell (active cell index). */
    const Vector<float> &
    fractions() const
    {
      return fraction;
    }

  private:
    Vector<float>         fraction;
    std::vector<Location> locations;
  };
} // namespace vefs

#endif
