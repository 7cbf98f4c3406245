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
  FlowElements<dim>::FlowElements(
    const FlowParameters                  &parameters,
    const unsigned int                     max_level,
    const std::vector<types::boundary_id> &finest_walls)
    : level_offset(parameters.flow_level_offset)
    , flow_level(static_cast<int>(max_level) -
                 static_cast<int>(parameters.flow_level_offset))
    , finest_walls(finest_walls)
    , all_components(dim + 1)
  {
    AssertThrow(flow_level >= 0, ExcInternalError());
    for (unsigned int depth = 1; depth <= level_offset; ++depth)
      descendant_vertex_weights.push_back(
        make_descendant_vertex_weights<dim>(depth));
    std::iota(all_components.begin(), all_components.end(), 0);
  }

  template <int dim>
  const typename FlowElements<dim>::CellWeights &
  FlowElements<dim>::weights_of(const CellIterator &cell) const
  {
    // The cell's place in its element's lattice: bit d of each child number
    // on the way up is one binary digit of its index in direction d.
    const unsigned int            depth = cell->level() - flow_level;
    std::array<unsigned int, dim> index{};
    CellIterator                  ancestor = cell;
    for (unsigned int digit = 0; digit < depth; ++digit)
      {
        const unsigned int child =
          ancestor->parent()->child_iterator_to_index(ancestor);
        for (unsigned int d = 0; d < dim; ++d)
          index[d] |= ((child >> d) & 1) << digit;
        ancestor = ancestor->parent();
      }
    unsigned int position = 0;
    for (unsigned int d = dim; d-- > 0;)
      position = (position << depth) | index[d];
    return descendant_vertex_weights[depth - 1][position];
  }

  template <int dim>
  void
  FlowElements<dim>::add_restricted_to_element(
    const FiniteElement<dim>        &fe,
    const CellIterator              &cell,
    const FullMatrix<double>        &fine,
    FullMatrix<double>              &coarse,
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
    const CellWeights  &weights = weights_of(cell);
    FullMatrix<double> &right   = restriction_scratch;
    right.reinit(n, n);
    for (const unsigned int component : components)
      for (unsigned int v = 0; v < n_vertices; ++v)
        {
          const unsigned int j = dof_of[component][v];
          for (const auto &[vertex, weight] : weights[v])
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
          for (const auto &[vertex, weight] : weights[v])
            {
              const unsigned int I = dof_of[component][vertex];
              for (const unsigned int j : rows)
                coarse(I, j) += weight * right(i, j);
            }
        }
  }

  template <int dim>
  void
  FlowElements<dim>::add_restricted_to_element(const FiniteElement<dim> &fe,
                                               const CellIterator       &cell,
                                               const FullMatrix<double> &fine,
                                               FullMatrix<double> &coarse) const
  {
    add_restricted_to_element(fe, cell, fine, coarse, all_components);
  }

  template <int dim>
  void
  FlowElements<dim>::add_restricted_to_element(const FiniteElement<dim> &fe,
                                               const CellIterator       &cell,
                                               const Vector<double>     &fine,
                                               Vector<double> &coarse) const
  {
    const unsigned int n       = fe.n_dofs_per_cell();
    const auto         dof_of  = dofs_by_component_and_vertex(fe);
    const CellWeights &weights = weights_of(cell);
    for (unsigned int i = 0; i < n; ++i)
      {
        const auto [component, cell_vertex] = fe.system_to_component_index(i);
        for (const auto &[vertex, weight] : weights[cell_vertex])
          coarse(dof_of[component][vertex]) += weight * fine(i);
      }
  }

  template <int dim>
  void
  FlowElements<dim>::classify(const DoFHandler<dim>   &dof_handler,
                              const LiquidDomain<dim> &domain)
  {
    this->domain = &domain;
    if (level_offset == 0)
      return;
    element_locations.assign(dof_handler.get_triangulation().n_active_cells(),
                             Location::empty);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          if (!on_coarser_element(cell))
            {
              element_locations[cell->active_cell_index()] =
                domain.location(cell);
              continue;
            }
          // An element once, from its first cell.
          if (!represents_element(cell))
            continue;
          const auto cells    = cells_of(element(cell));
          bool       all_full = true, all_empty = true;
          for (const auto &other : cells)
            {
              AssertThrow(other->is_locally_owned(),
                          ExcMessage("The cells of a flow element are not "
                                     "all on one rank; 'Flow/Flow cells' "
                                     "coarser than the finest needs them "
                                     "there."));
              all_full = all_full && domain.location(other) == Location::full;
              all_empty =
                all_empty && domain.location(other) == Location::empty;
            }
          const Location location = all_full    ? Location::full
                                    : all_empty ? Location::empty
                                                : Location::cut;
          for (const auto &other : cells)
            element_locations[other->active_cell_index()] = location;
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
  FlowElements<dim>::exchange_element_dofs(const DoFHandler<dim> &dof_handler,
                                           const unsigned int     fe_index,
                                           const IndexSet        &relevant)
  {
    ghost_element_dofs.clear();
    far_dofs.clear();
    if (level_offset == 0)
      return;
    using Dofs                    = std::vector<types::global_dof_index>;
    const unsigned int n_vertices = GeometryInfo<dim>::vertices_per_cell;
    const unsigned int n_components =
      dof_handler.get_fe_collection()[fe_index].n_components();
    GridTools::exchange_cell_data_to_ghosts<Dofs, DoFHandler<dim>>(
      dof_handler,
      [&](const typename DoFHandler<dim>::active_cell_iterator &cell)
        -> std_cxx17::optional<Dofs> {
        if (cell->active_fe_index() != fe_index || !on_coarser_element(cell))
          return {};
        Dofs dofs(n_vertices * n_components);
        // The element's cells are owned, its corner cells among them.
        for (unsigned int v = 0; v < n_vertices; ++v)
          for (unsigned int c = 0; c < n_components; ++c)
            dofs[v * n_components + c] =
              corner_cell(typename DoFHandler<dim>::cell_iterator(cell), v)
                ->vertex_dof_index(v, c, fe_index);
        return dofs;
      },
      [&](const typename DoFHandler<dim>::active_cell_iterator &cell,
          const Dofs                                           &dofs) {
        ghost_element_dofs[cell->active_cell_index()] = dofs;
      });

    far_dofs.set_size(dof_handler.n_dofs());
    std::vector<types::global_dof_index> far;
    for (const auto &[index, dofs] : ghost_element_dofs)
      for (const auto dof : dofs)
        if (!relevant.is_element(dof))
          far.push_back(dof);
    std::sort(far.begin(), far.end());
    far_dofs.add_indices(far.begin(), far.end());
    far_dofs.compress();
  }

  template <int dim>
  types::global_dof_index
  FlowElements<dim>::element_vertex_dof(
    const typename DoFHandler<dim>::cell_iterator &cell,
    const unsigned int                             v,
    const unsigned int                             c) const
  {
    const auto corner = corner_cell(cell, v);
    if (!corner->is_artificial())
      return corner->vertex_dof_index(v, c, corner->active_fe_index());
    const auto dofs = ghost_element_dofs.find(cell->active_cell_index());
    AssertThrow(dofs != ghost_element_dofs.end(), ExcInternalError());
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
    if (level_offset == 0)
      return;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (!cell->is_artificial() && cell->active_fe_index() == fe_index &&
          on_coarser_element(cell))
        {
          const CellWeights &weights = weights_of(cell);
          for (const unsigned int v : cell->vertex_indices())
            // A vertex of the element is its own unknown.
            if (weights[v].size() > 1)
              function(cell, v, weights[v]);
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
    // A cell on the finest level that is its own element (at a contact
    // wall) shares nodes with its coarser neighbours: those are constrained
    // to the neighbour's interpolant but keep their rows, as hanging nodes
    // do (the cell's matrix is added through the constraints, diagonal
    // included).
    if (!finest_walls.empty())
      {
        IndexSet                             own(dof_handler.n_dofs());
        std::vector<types::global_dof_index> cell_dofs;
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (!cell->is_artificial() && cell->active_fe_index() == fe_index &&
              cell->level() > flow_level && !on_coarser_element(cell))
            {
              cell_dofs.resize(cell->get_fe().n_dofs_per_cell());
              cell->get_dof_indices(cell_dofs);
              std::sort(cell_dofs.begin(), cell_dofs.end());
              own.add_indices(cell_dofs.begin(), cell_dofs.end());
            }
        own.compress();
        interpolated.subtract_set(own);
      }
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
                                    element_vertex_dof(cell, vertex, c),
                                    weight);
          }
      });
  }

  template class FlowElements<2>;
  template class FlowElements<3>;
} // namespace vefs
