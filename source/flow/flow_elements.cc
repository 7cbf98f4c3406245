#include <deal.II/grid/grid_tools.h>

#include <boost/serialization/vector.hpp>
#include <vefs/flow/flow_elements.h>

#include <algorithm>
#include <array>
#include <numeric>


namespace vefs
{
  namespace
  {
    /**
     * The dof of each component and vertex of a Q1 FESystem cell, looked
     * up once: FiniteElement::component_to_system_index() searches the
     * whole table on every call.
     */
    template <int dim>
    std::array<std::array<unsigned int, GeometryInfo<dim>::vertices_per_cell>,
               dim + 1>
    dofs_by_component_and_vertex(const FiniteElement<dim> &fe)
    {
      std::array<std::array<unsigned int, GeometryInfo<dim>::vertices_per_cell>,
                 dim + 1>
        dof_of;
      for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
        {
          const auto [component, vertex] = fe.system_to_component_index(i);
          dof_of[component][vertex]      = i;
        }
      return dof_of;
    }
  } // namespace

  template <int dim>
  FlowElements<dim>::FlowElements(const FlowParameters &parameters,
                                  const unsigned int    max_level)
    : child_vertex_weights(make_child_vertex_weights<dim>())
    , on_parents(parameters.flow_on_parents)
    , finest_level(max_level)
    , all_components(dim + 1)
  {
    std::iota(all_components.begin(), all_components.end(), 0);
  }

  template <int dim>
  void
  FlowElements<dim>::add_restricted_to_parent(
    const FiniteElement<dim>        &fe,
    const unsigned int               child,
    const FullMatrix<double>        &fine,
    FullMatrix<double>              &parent,
    const std::vector<unsigned int> &components) const
  {
    constexpr unsigned int n_vertices = GeometryInfo<dim>::vertices_per_cell;
    const unsigned int     n          = fe.n_dofs_per_cell();
    const auto             dof_of     = dofs_by_component_and_vertex(fe);
    std::vector<unsigned int> &rows   = restriction_rows;
    rows.clear();
    for (const unsigned int component : components)
      for (unsigned int v = 0; v < n_vertices; ++v)
        rows.push_back(dof_of[component][v]);

    // fine P in the rows of the components, then P^T (fine P).
    FullMatrix<double> &right = restriction_scratch;
    right.reinit(n, n);
    for (const unsigned int component : components)
      for (unsigned int v = 0; v < n_vertices; ++v)
        {
          const unsigned int j = dof_of[component][v];
          for (const auto &[vertex, weight] : child_vertex_weights[child][v])
            {
              const unsigned int J = dof_of[component][vertex];
              for (const unsigned int i : rows)
                right(i, J) += fine(i, j) * weight;
            }
        }
    for (const unsigned int component : components)
      for (unsigned int v = 0; v < n_vertices; ++v)
        {
          const unsigned int i = dof_of[component][v];
          for (const auto &[vertex, weight] : child_vertex_weights[child][v])
            {
              const unsigned int I = dof_of[component][vertex];
              for (const unsigned int j : rows)
                parent(I, j) += weight * right(i, j);
            }
        }
  }

  template <int dim>
  void
  FlowElements<dim>::add_restricted_to_parent(const FiniteElement<dim> &fe,
                                              const unsigned int        child,
                                              const FullMatrix<double> &fine,
                                              FullMatrix<double> &parent) const
  {
    add_restricted_to_parent(fe, child, fine, parent, all_components);
  }

  template <int dim>
  void
  FlowElements<dim>::add_restricted_to_parent(const FiniteElement<dim> &fe,
                                              const unsigned int        child,
                                              const Vector<double>     &fine,
                                              Vector<double> &parent) const
  {
    const unsigned int n      = fe.n_dofs_per_cell();
    const auto         dof_of = dofs_by_component_and_vertex(fe);
    for (unsigned int i = 0; i < n; ++i)
      {
        const auto [component, child_vertex] = fe.system_to_component_index(i);
        for (const auto &[vertex, weight] :
             child_vertex_weights[child][child_vertex])
          parent(dof_of[component][vertex]) += weight * fine(i);
      }
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
          if (!on_parent(cell))
            element_locations[cell->active_cell_index()] =
              domain.location(cell);
          // A family once, from its first child.
          else if (cell->parent()->child(0) == cell)
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
              const Location location = all_full    ? Location::full
                                        : all_empty ? Location::empty
                                                    : Location::cut;
              for (unsigned int c = 0; c < parent->n_children(); ++c)
                element_locations[parent->child(c)->active_cell_index()] =
                  location;
            }
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
                                          const unsigned int     fe_index,
                                          const IndexSet        &relevant)
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
    const typename DoFHandler<dim>::cell_iterator &cell,
    const unsigned int                             v,
    const unsigned int                             c) const
  {
    const auto sibling = cell->parent()->child(v);
    if (!sibling->is_artificial())
      return sibling->vertex_dof_index(v, c, sibling->active_fe_index());
    const auto dofs = ghost_parent_dofs.find(cell->active_cell_index());
    AssertThrow(dofs != ghost_parent_dofs.end(), ExcInternalError());
    return dofs->second[v * cell->get_fe().n_components() + c];
  }

  template <int dim>
  template <typename VertexFunction>
  void
  FlowElements<dim>::for_each_interpolated_vertex(
    const DoFHandler<dim> &dof_handler,
    const unsigned int     fe_index,
    const VertexFunction  &function) const
  {
    if (!on_parents)
      return;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (!cell->is_artificial() && cell->active_fe_index() == fe_index &&
          on_parent(cell))
        {
          const unsigned int child =
            cell->parent()->child_iterator_to_index(cell);
          for (const unsigned int v : cell->vertex_indices())
            // A vertex of the parent is its own unknown.
            if (child_vertex_weights[child][v].size() > 1)
              function(cell, v, child_vertex_weights[child][v]);
        }
  }

  template <int dim>
  IndexSet
  FlowElements<dim>::interpolated_dofs(const DoFHandler<dim> &dof_handler,
                                       const unsigned int     fe_index) const
  {
    const unsigned int n_components =
      dof_handler.get_fe_collection()[fe_index].n_components();
    std::vector<types::global_dof_index> dofs;
    for_each_interpolated_vertex(
      dof_handler,
      fe_index,
      [&](const auto &cell, const unsigned int v, const auto &) {
        for (unsigned int c = 0; c < n_components; ++c)
          dofs.push_back(cell->vertex_dof_index(v, c, fe_index));
      });
    std::sort(dofs.begin(), dofs.end());
    dofs.erase(std::unique(dofs.begin(), dofs.end()), dofs.end());
    IndexSet interpolated(dof_handler.n_dofs());
    interpolated.add_indices(dofs.begin(), dofs.end());
    interpolated.compress();
    return interpolated;
  }

  template <int dim>
  void
  FlowElements<dim>::make_interpolation_constraints(
    const DoFHandler<dim>     &dof_handler,
    const unsigned int         fe_index,
    AffineConstraints<double> &constraints) const
  {
    const unsigned int n_components =
      dof_handler.get_fe_collection()[fe_index].n_components();
    for_each_interpolated_vertex(
      dof_handler,
      fe_index,
      [&](const auto &cell, const unsigned int v, const auto &weights) {
        for (unsigned int c = 0; c < n_components; ++c)
          {
            const types::global_dof_index dof =
              cell->vertex_dof_index(v, c, fe_index);
            if (constraints.is_constrained(dof))
              continue;
            constraints.add_line(dof);
            for (const auto &[vertex, weight] : weights)
              constraints.add_entry(dof,
                                    parent_vertex_dof(cell, vertex, c),
                                    weight);
          }
      });
  }

  template class FlowElements<2>;
  template class FlowElements<3>;
} // namespace vefs
