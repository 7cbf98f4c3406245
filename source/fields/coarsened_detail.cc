#include <deal.II/grid/grid_tools.h>

#include <vefs/compat/box_mesh_locator.h>
#include <vefs/fields/coarsened_detail.h>

#include <cstring>

namespace vefs
{
  namespace
  {
    template <int dim>
    typename DoFHandler<dim>::active_cell_iterator
    dof_cell(const DoFHandler<dim>                            &dof_handler,
             const typename Triangulation<dim>::cell_iterator &cell)
    {
      return typename DoFHandler<dim>::active_cell_iterator(
        &dof_handler.get_triangulation(),
        cell->level(),
        cell->index(),
        &dof_handler);
    }
  } // namespace

  template <int dim>
  void
  CoarsenedDetail<dim>::attach(parallel::distributed::Triangulation<dim> &mesh,
                               const DoFHandler<dim> &dof_handler,
                               const VectorType      &fields,
                               const unsigned int     components)
  {
    AssertThrow(handle == none, ExcInternalError());
    AssertThrow(n_components == 0 || n_components == components,
                ExcInternalError());
    n_components                = components;
    const unsigned int n_values = n_points * n_components;
    handle                      = mesh.register_data_attach(
      [this, &dof_handler, &fields, n_values](
        const typename Triangulation<dim>::cell_iterator &cell,
        const typename Triangulation<dim>::CellStatus     status) {
        std::vector<char> buffer;
        if (status == Triangulation<dim>::CELL_COARSEN)
          {
            std::vector<double> family(n_values);
            for (unsigned int child = 0; child < cell->n_children(); ++child)
              {
                const auto fine = dof_cell(dof_handler, cell->child(child));
                for (const unsigned int v : fine->vertex_indices())
                  {
                    double *point =
                      &family[lattice_point(child, v) * n_components];
                    for (unsigned int c = 0; c < n_components; ++c)
                      point[c] = fields(fine->vertex_dof_index(v, c));
                  }
              }
            buffer.resize(n_values * sizeof(double));
            std::memcpy(buffer.data(), family.data(), buffer.size());
          }
        else if (const double *kept = lattice(
                   typename Triangulation<dim>::active_cell_iterator(cell)))
          {
            buffer.resize(n_values * sizeof(double));
            std::memcpy(buffer.data(), kept, buffer.size());
          }
        return buffer;
      },
      /*returns_variable_size_data=*/true);
  }

  template <int dim>
  void
  CoarsenedDetail<dim>::unpack(parallel::distributed::Triangulation<dim> &mesh,
                               const DoFHandler<dim> &dof_handler,
                               VectorType            &fields)
  {
    AssertThrow(handle != none, ExcInternalError());
    offsets.assign(mesh.n_active_cells(), none);
    values.clear();
    const unsigned int  n_values = n_points * n_components;
    std::vector<double> packed(n_values);
    mesh.notify_ready_to_unpack(
      handle,
      [&](
        const typename Triangulation<dim>::cell_iterator               &cell,
        const typename Triangulation<dim>::CellStatus                   status,
        const boost::iterator_range<std::vector<char>::const_iterator> &data) {
        if (data.empty())
          return;
        AssertThrow(static_cast<std::size_t>(data.size()) ==
                      n_values * sizeof(double),
                    ExcInternalError());
        std::memcpy(packed.data(), &*data.begin(), data.size());
        if (status != Triangulation<dim>::CELL_REFINE)
          {
            store(typename Triangulation<dim>::active_cell_iterator(cell),
                  packed.data());
            return;
          }
        // Refined again (the 2:1 balance): the children's vertices are the
        // lattice, so they take the values they had.
        for (unsigned int child = 0; child < cell->n_children(); ++child)
          {
            const auto fine = dof_cell(dof_handler, cell->child(child));
            for (const unsigned int v : fine->vertex_indices())
              {
                const double *point =
                  &packed[lattice_point(child, v) * n_components];
                for (unsigned int c = 0; c < n_components; ++c)
                  {
                    const auto dof = fine->vertex_dof_index(v, c);
                    if (fields.in_local_range(dof))
                      fields(dof) = point[c];
                  }
              }
          }
      });
    handle = none;
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
        const double *point  = lattice + lattice_point(child, v) * n_components;
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
    AssertThrow(handle == none, ExcInternalError());
    offsets.clear();
    values.clear();
  }

  template class CoarsenedDetail<2>;
  template class CoarsenedDetail<3>;
} // namespace vefs
