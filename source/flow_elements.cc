#include <deal.II/dofs/dof_tools.h>
#include <deal.II/grid/grid_tools.h>

#include <boost/serialization/vector.hpp>
#include <vefs/flow_elements.h>

#include <array>

namespace vefs
{
  template <int dim>
  FlowElements<dim>::FlowElements(const Parameters &parameters)
    : on_parents(parameters.flow_on_parents)
    , finest_level(parameters.max_level)
  {
  }

  template <int dim>
  void
  FlowElements<dim>::classify(const DoFHandler<dim>   &dof_handler,
                              const LiquidDomain<dim> &domain)
  {
    this->domain = &domain;
    if (!on_parents)
      return;
    element_locations.assign(dof_handler.get_triangulation().n_active_cells(),
                             Location::empty);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          Location location = domain.location(cell);
          if (on_parent(cell))
            {
              const auto parent   = cell->parent();
              bool       all_full = true, all_empty = true;
              for (unsigned int c = 0; c < parent->n_children(); ++c)
                {
                  // Children of the finest level are active.
                  const typename Triangulation<dim>::active_cell_iterator
                    child = parent->child(c);
                  AssertThrow(child->is_locally_owned(),
                              ExcMessage("The children of a parent are not "
                                         "all on one rank; 'Flow cells = "
                                         "parents' needs them there."));
                  all_full =
                    all_full && domain.location(child) == Location::full;
                  all_empty =
                    all_empty && domain.location(child) == Location::empty;
                }
              location = all_full    ? Location::full
                         : all_empty ? Location::empty
                                     : Location::cut;
            }
          element_locations[cell->active_cell_index()] = location;
        }
    GridTools::exchange_cell_data_to_ghosts<unsigned char, DoFHandler<dim>>(
      dof_handler,
      [&](const typename DoFHandler<dim>::active_cell_iterator &cell) {
        return static_cast<unsigned char>(
          element_locations[cell->active_cell_index()]);
      },
      [&](const typename DoFHandler<dim>::active_cell_iterator &cell,
          const unsigned char                                  &location) {
        element_locations[cell->active_cell_index()] =
          static_cast<Location>(location);
      });
  }

  template <int dim>
  void
  FlowElements<dim>::exchange_parent_dofs(const DoFHandler<dim> &dof_handler,
                                          const unsigned int     fe_index)
  {
    ghost_parent_dofs.clear();
    far_dofs.clear();
    if (!on_parents)
      return;
    using Dofs                    = std::vector<types::global_dof_index>;
    const unsigned int n_vertices = GeometryInfo<dim>::vertices_per_cell;
    const unsigned int n_components =
      dof_handler.get_fe_collection()[fe_index].n_components();
    GridTools::exchange_cell_data_to_ghosts<Dofs, DoFHandler<dim>>(
      dof_handler,
      [&](const typename DoFHandler<dim>::active_cell_iterator &cell)
        -> std_cxx17::optional<Dofs> {
        if (cell->active_fe_index() != fe_index || !on_parent(cell))
          return {};
        Dofs dofs(n_vertices * n_components);
        // Child v holds the parent's vertex v; the children are owned.
        for (unsigned int v = 0; v < n_vertices; ++v)
          for (unsigned int c = 0; c < n_components; ++c)
            dofs[v * n_components + c] =
              cell->parent()->child(v)->vertex_dof_index(v, c, fe_index);
        return dofs;
      },
      [&](const typename DoFHandler<dim>::active_cell_iterator &cell,
          const Dofs                                           &dofs) {
        ghost_parent_dofs[cell->active_cell_index()] = dofs;
      });

    IndexSet relevant;
    DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
    far_dofs.set_size(dof_handler.n_dofs());
    std::vector<types::global_dof_index> far;
    for (const auto &[index, dofs] : ghost_parent_dofs)
      for (const auto dof : dofs)
        if (!relevant.is_element(dof))
          far.push_back(dof);
    std::sort(far.begin(), far.end());
    far_dofs.add_indices(far.begin(), far.end());
    far_dofs.compress();
  }

  template <int dim>
  types::global_dof_index
  FlowElements<dim>::parent_vertex_dof(
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    const unsigned int                                    v,
    const unsigned int                                    c) const
  {
    const auto sibling = cell->parent()->child(v);
    if (!sibling->is_artificial())
      return sibling->vertex_dof_index(v, c, sibling->active_fe_index());
    const auto dofs = ghost_parent_dofs.find(cell->active_cell_index());
    AssertThrow(dofs != ghost_parent_dofs.end(), ExcInternalError());
    return dofs->second[v * cell->get_fe().n_components() + c];
  }

  template <int dim>
  void
  FlowElements<dim>::make_interpolation_constraints(
    const DoFHandler<dim>     &dof_handler,
    const unsigned int         fe_index,
    AffineConstraints<double> &constraints) const
  {
    if (!on_parents)
      return;
    constexpr unsigned int n_vertices = GeometryInfo<dim>::vertices_per_cell;
    const unsigned int     n_components =
      dof_handler.get_fe_collection()[fe_index].n_components();
    std::array<double, n_vertices>                  weights;
    std::array<types::global_dof_index, n_vertices> parent_dofs;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (!cell->is_artificial() && cell->active_fe_index() == fe_index &&
          on_parent(cell))
        {
          const auto         parent = cell->parent();
          const unsigned int child  = parent->child_iterator_to_index(cell);
          for (const unsigned int v : cell->vertex_indices())
            {
              // The vertex in the parent's reference cell: child c's vertex
              // v sits at (bit d of c + bit d of v) / 2 in direction d
              // (deal.II numbers children as the vertices they hold).
              Point<dim> xi;
              bool       is_parent_vertex = true;
              for (unsigned int d = 0; d < dim; ++d)
                {
                  xi[d] = 0.5 * (((child >> d) & 1) + ((v >> d) & 1));
                  if (xi[d] == 0.5)
                    is_parent_vertex = false;
                }
              if (is_parent_vertex)
                continue;
              for (unsigned int j = 0; j < n_vertices; ++j)
                {
                  weights[j] = 1;
                  for (unsigned int d = 0; d < dim; ++d)
                    weights[j] *= ((j >> d) & 1) ? xi[d] : 1 - xi[d];
                }
              for (unsigned int c = 0; c < n_components; ++c)
                {
                  for (unsigned int j = 0; j < n_vertices; ++j)
                    if (weights[j] != 0)
                      parent_dofs[j] = parent_vertex_dof(cell, j, c);
                  const types::global_dof_index dof =
                    cell->vertex_dof_index(v, c, fe_index);
                  if (constraints.is_constrained(dof))
                    continue;
                  constraints.add_line(dof);
                  for (unsigned int j = 0; j < n_vertices; ++j)
                    if (weights[j] != 0)
                      constraints.add_entry(dof, parent_dofs[j], weights[j]);
                }
            }
        }
  }

  template class FlowElements<2>;
  template class FlowElements<3>;
} // namespace vefs
