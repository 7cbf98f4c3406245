#include <deal.II/grid/grid_tools.h>

#include <vefs/compat/box_mesh_locator.h>
#include <vefs/fields/coarsened_detail.h>


namespace vefs
{
  template <int dim>
  void
  CoarsenedDetail<dim>::from_fields(const TransportedFields<dim> &fields)
  {
    AssertThrow(n_components == 0 || n_components == fields.n_components,
                ExcInternalError());
    this->fields = &fields;
    n_components = fields.n_components;
  }

  template <int dim>
  std::vector<std::pair<unsigned int, unsigned int>>
  CoarsenedDetail<dim>::components() const
  {
    std::vector<std::pair<unsigned int, unsigned int>> result;
    for (unsigned int c = 0; c < n_components; ++c)
      result.emplace_back(0, c);
    return result;
  }

  template <int dim>
  std::vector<double>
  CoarsenedDetail<dim>::pack(
    const typename Triangulation<dim>::cell_iterator &cell,
    const CellStatus                                  status) const
  {
    AssertThrow(fields, ExcInternalError());
    const unsigned int n_values = n_points * n_components;
    if (status == Triangulation<dim>::CELL_COARSEN)
      {
        std::vector<double> family(n_values);
        for (unsigned int child = 0; child < cell->n_children(); ++child)
          {
            const auto fine = fields->cell_of(cell->child(child));
            for (const unsigned int v : fine->vertex_indices())
              {
                double *point =
                  &family[FamilyLattice<dim>::point(child, v) * n_components];
                for (unsigned int c = 0; c < n_components; ++c)
                  point[c] = fields->value_at(fine, v, c);
              }
          }
        return family;
      }
    if (const double *kept =
          lattice(typename Triangulation<dim>::active_cell_iterator(cell)))
      return std::vector<double>(kept, kept + n_values);
    return {};
  }

  template <int dim>
  void
  CoarsenedDetail<dim>::start_keeping(const Triangulation<dim> &mesh)
  {
    offsets.assign(mesh.n_active_cells(), none);
    values.clear();
  }

  template <int dim>
  void
  CoarsenedDetail<dim>::keep(
    const typename Triangulation<dim>::active_cell_iterator &cell,
    const double                                            *lattice)
  {
    store(cell, lattice);
  }

  template <int dim>
  void
  CoarsenedDetail<dim>::add_values(const double     *lattice,
                                   const Point<dim> &xi,
                                   double           *values) const
  {
    unsigned int child = 0;
    Point<dim>   xi_child;
    for (unsigned int d = 0; d < dim; ++d)
      {
        const unsigned int upper = xi[d] >= 0.5 ? 1 : 0;
        child |= upper << d;
        xi_child[d] = 2 * xi[d] - upper;
      }
    for (const unsigned int v : GeometryInfo<dim>::vertex_indices())
      {
        const double  weight = BoxMeshLocator<dim>::vertex_weight(xi_child, v);
        const double *point =
          lattice + FamilyLattice<dim>::point(child, v) * n_components;
        for (unsigned int c = 0; c < n_components; ++c)
          values[c] += weight * point[c];
      }
  }

  template <int dim>
  void
  CoarsenedDetail<dim>::update_ghosts(
    const parallel::distributed::Triangulation<dim> &mesh)
  {
    if (offsets.empty())
      return;
    using Cell = typename Triangulation<dim>::active_cell_iterator;
    const unsigned int n_values = n_points * n_components;
    GridTools::exchange_cell_data_to_ghosts<std::vector<double>,
                                            Triangulation<dim>>(
      mesh,
      [this, n_values](const Cell &cell) {
        std_cxx17::optional<std::vector<double>> data;
        if (const double *kept = lattice(cell))
          data = std::vector<double>(kept, kept + n_values);
        return data;
      },
      [this](const Cell &cell, const std::vector<double> &data) {
        store(cell, data.data());
      });
  }

  template <int dim>
  void
  CoarsenedDetail<dim>::store(
    const typename Triangulation<dim>::active_cell_iterator &cell,
    const double                                            *lattice)
  {
    offsets[cell->active_cell_index()] = values.size();
    values.insert(values.end(), lattice, lattice + n_points * n_components);
  }

  template <int dim>
  void
  CoarsenedDetail<dim>::clear()
  {
    offsets.clear();
    values.clear();
  }

  template class CoarsenedDetail<2>;
  template class CoarsenedDetail<3>;
} // namespace vefs
