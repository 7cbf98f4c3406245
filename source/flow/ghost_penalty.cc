#include <deal.II/base/quadrature_lib.h>

#include <vefs/flow/ghost_penalty.h>

#include <algorithm>
#include <array>
#include <utility>

namespace vefs
{
  template <int dim>
  GhostPenalty<dim>::GhostPenalty(const FlowStepParameters &parameters,
                                  const Rheology<dim>      &rheology,
                                  const FiniteElement<dim> &flow_fe,
                                  const FlowElements<dim>  &elements,
                                  const double              tau)
    : parameters(parameters)
    , mass_tau(parameters.mass_step(tau))
    , mu(rheology.effective_viscosity(tau))
    , flow_fe(flow_fe)
    , elements(elements)
    , interface_values(flow_fe,
                       QGauss<dim - 1>(2),
                       update_gradients | update_normal_vectors |
                         update_JxW_values)
  {
  }

  template <int dim>
  void
  GhostPenalty<dim>::for_each_face(const DoFHandler<dim> &dof_handler,
                                   const bool             matrices_wanted,
                                   const FaceAction      &action,
                                   const Faces            faces)
  {
    using Location = typename LiquidDomain<dim>::Location;
    if (matrices_wanted && wall_faces_kept && faces == Faces::next_to_walls)
      {
        for (const KeptFace &face : kept_faces)
          {
            recall_face(face);
            action(matrix, schur, face.dofs);
          }
        return;
      }
    const bool keep = matrices_wanted && faces == Faces::all;
    if (keep)
      kept_faces.clear();
    std::vector<types::global_dof_index> dofs, cell_dofs, neighbor_dofs;
    // The sparsity pattern needs only the dofs of both elements, and
    // couples each component with itself only.
    const auto add_to_pattern = [&](const auto &cell, const auto &neighbor) {
      get_element_dofs(cell, cell_dofs);
      get_element_dofs(neighbor, neighbor_dofs);
      for (unsigned int c = 0; c < flow_fe.n_components(); ++c)
        {
          dofs.clear();
          for (unsigned int i = 0; i < cell_dofs.size(); ++i)
            if (flow_fe.system_to_component_index(i).first == c)
              {
                dofs.push_back(cell_dofs[i]);
                dofs.push_back(neighbor_dofs[i]);
              }
          std::sort(dofs.begin(), dofs.end());
          dofs.erase(std::unique(dofs.begin(), dofs.end()), dofs.end());
          action(matrix, schur, dofs);
        }
    };
    // Between two cut cells each side weighs in with half the penalty and
    // its own h.
    const auto weights_of_face =
      [&](const auto &cell, const auto &neighbor, const bool neighbor_is_cut) {
        return neighbor_is_cut ? face_weights(elements.size(cell), 0.5) +
                                   face_weights(elements.size(neighbor), 0.5)
                               : face_weights(elements.size(cell), 1.);
      };
    // Whether this side adds the face to @p neighbor: liquid beyond, a face
    // of the kind asked for, and a face between two cut cells, seen from
    // both, belongs to the side with the smaller CellId (of the cells, or
    // of the elements), on whichever rank owns that side.
    const auto claims_face = [&](const bool    next_to_walls,
                                 const auto   &neighbor,
                                 const CellId &own_id,
                                 const CellId &neighbor_id) {
      if (!elements.has_liquid(neighbor) ||
          (faces == Faces::next_to_walls && !next_to_walls))
        return false;
      return !(elements.location(neighbor) == Location::cut &&
               neighbor_id < own_id);
    };
    const auto visit = [&](const auto        &cell,
                           const unsigned int face,
                           const unsigned int subface,
                           const auto        &neighbor,
                           const unsigned int neighbor_face,
                           const unsigned int neighbor_subface) {
      // Within one flow element (FlowElements) the normal derivatives do
      // not jump.
      const bool next_to_walls = elements.element(cell)->at_boundary() ||
                                 elements.element(neighbor)->at_boundary();
      if (elements.same_element(cell, neighbor) ||
          !claims_face(next_to_walls, neighbor, cell->id(), neighbor->id()))
        return;
      const bool neighbor_is_cut = elements.location(neighbor) == Location::cut;
      if (!matrices_wanted)
        {
          add_to_pattern(cell, neighbor);
          return;
        }
      interface_values
        .reinit(cell, face, subface, neighbor, neighbor_face, neighbor_subface);
      expand_to_elements(cell, neighbor);
      const Weights weights = weights_of_face(cell, neighbor, neighbor_is_cut);
      compute(weights);
      if (keep && next_to_walls)
        keep_face(element_dofs);
      action(matrix, schur, element_dofs);
    };

    // A fine face, whatever the sizes of the cells and elements on its
    // sides: through the interface values of the two cells.
    const auto visit_fine_face = [&](const auto &cell, const unsigned int f) {
      if (cell->face(f)->has_children())
        {
          const unsigned int neighbor_face = cell->neighbor_face_no(f);
          for (unsigned int s = 0; s < cell->face(f)->n_children(); ++s)
            visit(cell,
                  f,
                  s,
                  cell->neighbor_child_on_subface(f, s),
                  neighbor_face,
                  numbers::invalid_unsigned_int);
        }
      else if (cell->neighbor_is_coarser(f))
        {
          const auto [neighbor_face, neighbor_subface] =
            cell->neighbor_of_coarser_neighbor(f);
          visit(cell,
                f,
                numbers::invalid_unsigned_int,
                cell->neighbor(f),
                neighbor_face,
                neighbor_subface);
        }
      else
        visit(cell,
              f,
              numbers::invalid_unsigned_int,
              cell->neighbor(f),
              cell->neighbor_of_neighbor(f),
              numbers::invalid_unsigned_int);
    };

    // The whole face f between the element of @p cell and one of the same
    // size (between_equal_elements()), in closed form.
    const auto visit_between_equal = [&](const auto        &cell,
                                         const unsigned int f) {
      const unsigned int direction = f / 2;
      auto               neighbor  = cell->neighbor(f);
      // A coarser element beyond: its cell at the lowest corner of the face.
      while (neighbor->has_children())
        neighbor = neighbor->child((1 - f % 2) << direction);
      const auto element          = elements.element(cell);
      const auto neighbor_element = elements.element(neighbor);
      const bool next_to_walls =
        element->at_boundary() || neighbor_element->at_boundary();
      if (!claims_face(next_to_walls,
                       neighbor,
                       element->id(),
                       neighbor_element->id()))
        return;
      const bool neighbor_is_cut = elements.location(neighbor) == Location::cut;
      if (!matrices_wanted)
        {
          add_to_pattern(cell, neighbor);
          return;
        }
      const Weights weights = weights_of_face(cell, neighbor, neighbor_is_cut);
      if (f % 2 == 1)
        compute_between_equal_elements(cell, neighbor, direction, weights);
      else
        compute_between_equal_elements(neighbor, cell, direction, weights);
      if (keep && next_to_walls)
        keep_face(element_dofs);
      action(matrix, schur, element_dofs);
    };

    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && elements.location(cell) == Location::cut)
        {
          if (elements.on_coarser_element(cell))
            {
              // A coarser element once, through one of its cells, face by
              // face of the element: the faces between its cells are
              // within the element.
              if (!elements.represents_element(cell))
                continue;
              const auto element = elements.element(cell);
              const auto cells   = elements.cells_of(element);
              for (const unsigned int f : element->face_indices())
                {
                  if (element->at_boundary(f))
                    continue;
                  // The element's cells on face f, the first at its
                  // lowest corner there.
                  std::vector<typename DoFHandler<dim>::active_cell_iterator>
                    on_face;
                  for (const auto &other : cells)
                    if (!elements.same_element(other, other->neighbor(f)))
                      on_face.push_back(other);
                  if (between_equal_elements(on_face.front(), f))
                    visit_between_equal(on_face.front(), f);
                  else
                    for (const auto &side : on_face)
                      visit_fine_face(side, f);
                }
              continue;
            }
          for (const unsigned int f : cell->face_indices())
            {
              if (cell->at_boundary(f))
                continue;
              if (between_equal_elements(cell, f))
                visit_between_equal(cell, f);
              else
                visit_fine_face(cell, f);
            }
        }
    if (keep)
      wall_faces_kept = true;
  }

  template <int dim>
  void
  GhostPenalty<dim>::keep_face(const std::vector<types::global_dof_index> &dofs)
  {
    KeptFace face{dofs, component, {}, {}};
    // Reserved: the faces between parents hold up to 64 dofs, and growing
    // the vectors entry by entry took 7 % of a step at 2.5 mm.
    std::vector<unsigned int> n_of_component(flow_fe.n_components(), 0);
    for (const unsigned int c : component)
      ++n_of_component[c];
    std::size_t n_entries = 0;
    for (const unsigned int n : n_of_component)
      n_entries += n * n;
    face.matrix.reserve(n_entries);
    face.schur.reserve(n_of_component[dim] * n_of_component[dim]);
    for (unsigned int i = 0; i < dofs.size(); ++i)
      for (unsigned int j = 0; j < dofs.size(); ++j)
        if (component[i] == component[j])
          {
            face.matrix.push_back(matrix(i, j));
            if (component[i] == dim)
              face.schur.push_back(schur(i, j));
          }
    kept_faces.push_back(std::move(face));
  }

  template <int dim>
  void
  GhostPenalty<dim>::recall_face(const KeptFace &face)
  {
    const unsigned int n = face.dofs.size();
    matrix.reinit(n, n);
    schur.reinit(n, n);
    unsigned int next = 0, next_schur = 0;
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        if (face.component[i] == face.component[j])
          {
            matrix(i, j) = face.matrix[next++];
            if (face.component[i] == dim)
              schur(i, j) = face.schur[next_schur++];
          }
  }

  template <int dim>
  typename GhostPenalty<dim>::Weights
  GhostPenalty<dim>::face_weights(const double h, const double share) const
  {
    const double rho   = parameters.material.density;
    const double gamma = parameters.solver.ghost_penalty * share;
    const double tau_K = parameters.solver.pressure_stabilization /
                         (rho / mass_tau + 4 * mu / (h * h));
    return {gamma * (mu + rho * h * h / mass_tau) * h,
            gamma * tau_K * h,
            gamma * (mass_tau / rho + tau_K) * h};
  }

  template <int dim>
  void
  GhostPenalty<dim>::get_element_dofs(
    const typename DoFHandler<dim>::cell_iterator &cell,
    std::vector<types::global_dof_index>          &dofs) const
  {
    dofs.resize(flow_fe.n_dofs_per_cell());
    if (!elements.on_coarser_element(cell))
      {
        cell->get_dof_indices(dofs);
        return;
      }
    for (unsigned int i = 0; i < dofs.size(); ++i)
      {
        const auto [c, v] = flow_fe.system_to_component_index(i);
        dofs[i]           = elements.element_vertex_dof(cell, v, c);
      }
  }

  template <int dim>
  void
  GhostPenalty<dim>::expand_to_elements(
    const typename DoFHandler<dim>::cell_iterator &cell,
    const typename DoFHandler<dim>::cell_iterator &neighbor)
  {
    const auto &interface_dofs = interface_values.get_interface_dof_indices();
    const unsigned int n       = interface_dofs.size();
    expansion.resize(n);
    if (!elements.on_coarser_element(cell) &&
        !elements.on_coarser_element(neighbor))
      {
        // Both cells are their own elements: the interface dofs themselves.
        element_dofs = interface_dofs;
        component.resize(n);
        for (unsigned int k = 0; k < n; ++k)
          {
            const auto dof_pair =
              interface_values.interface_dof_to_dof_indices(k);
            component[k] =
              flow_fe
                .system_to_component_index(
                  dof_pair[0] != numbers::invalid_unsigned_int ? dof_pair[0]
                                                               : dof_pair[1])
                .first;
            expansion[k].assign(1, {k, 1.});
          }
        return;
      }
    element_dofs.clear();
    component.clear();
    // The index of an element dof in element_dofs, added if new.
    const auto index_of = [&](const types::global_dof_index dof,
                              const unsigned int            c) {
      const auto found =
        std::find(element_dofs.begin(), element_dofs.end(), dof);
      if (found != element_dofs.end())
        return static_cast<unsigned int>(found - element_dofs.begin());
      element_dofs.push_back(dof);
      component.push_back(c);
      return static_cast<unsigned int>(element_dofs.size() - 1);
    };
    for (unsigned int k = 0; k < n; ++k)
      {
        const auto dof_pair = interface_values.interface_dof_to_dof_indices(k);
        // A dof of a side on a coarser element is interpolated from the
        // element's vertices (a dof both sides share, the same way from
        // either).
        const bool from_cell = dof_pair[0] != numbers::invalid_unsigned_int &&
                               elements.on_coarser_element(cell);
        const bool from_neighbor =
          !from_cell && dof_pair[1] != numbers::invalid_unsigned_int &&
          elements.on_coarser_element(neighbor);
        const auto        &side = from_neighbor ? neighbor : cell;
        const unsigned int local =
          from_neighbor                                  ? dof_pair[1]
          : dof_pair[0] != numbers::invalid_unsigned_int ? dof_pair[0]
                                                         : dof_pair[1];
        const auto [c, v] = flow_fe.system_to_component_index(local);
        expansion[k].clear();
        if (from_cell || from_neighbor)
          {
            for (const auto &[vertex, weight] :
                 elements.vertex_weights(side, v))
              expansion[k].emplace_back(
                index_of(elements.element_vertex_dof(side, vertex, c), c),
                weight);
          }
        else
          expansion[k].emplace_back(index_of(interface_dofs[k], c), 1.);
      }
  }

  template <int dim>
  bool
  GhostPenalty<dim>::between_equal_elements(
    const typename DoFHandler<dim>::cell_iterator &cell,
    const unsigned int                             f) const
  {
    const auto element  = elements.element(cell);
    const auto neighbor = cell->neighbor(f);
    // The neighbour's element: its own if it is active or lies within a
    // coarser element; a refined cell coarser than the elements is none.
    if (neighbor->has_children() && !elements.on_coarser_element(neighbor) &&
        !elements.on_coarser_element(neighbor->child(0)))
      return false;
    const typename FlowElements<dim>::CellIterator neighbor_element =
      elements.element(neighbor);
    if (neighbor_element->level() != element->level())
      return false;
    const Tensor<1, dim> extent = internal::box_extent<dim>(element);
    const Tensor<1, dim> neighbor_extent =
      internal::box_extent<dim>(neighbor_element);
    for (unsigned int d = 0; d < dim; ++d)
      if (std::abs(neighbor_extent[d] - extent[d]) > 1e-10 * extent[d])
        return false;
    return true;
  }

  template <int dim>
  void
  GhostPenalty<dim>::compute_between_equal_elements(
    const typename DoFHandler<dim>::cell_iterator &lower,
    const typename DoFHandler<dim>::cell_iterator &upper,
    const unsigned int                             direction,
    const Weights                                 &weights)
  {
    constexpr unsigned int n_face_vertices = 1u << (dim - 1);
    const unsigned int     n_components    = flow_fe.n_components();
    const unsigned int     n               = 3 * n_face_vertices * n_components;
    // The vertex of a cell with @p bit in the face's direction and the
    // other directions' bits @p t.
    const auto vertex = [direction](const unsigned int t,
                                    const unsigned int bit) {
      return (t & ((1u << direction) - 1)) | (bit << direction) |
             ((t >> direction) << (direction + 1));
    };
    const auto dof = [&](const typename DoFHandler<dim>::cell_iterator &side,
                         const unsigned int                             v,
                         const unsigned int                             c) {
      return elements.on_coarser_element(side)
               ? elements.element_vertex_dof(side, v, c)
               : side->vertex_dof_index(v, c, side->active_fe_index());
    };
    // By component, then the layers of vertices (the lower element's far
    // one, the face, the upper element's far one), then the face's vertex.
    element_dofs.resize(n);
    component.resize(n);
    for (unsigned int c = 0; c < n_components; ++c)
      for (unsigned int t = 0; t < n_face_vertices; ++t)
        {
          const unsigned int i                  = c * 3 * n_face_vertices + t;
          element_dofs[i]                       = dof(lower, vertex(t, 0), c);
          element_dofs[i + n_face_vertices]     = dof(lower, vertex(t, 1), c);
          element_dofs[i + 2 * n_face_vertices] = dof(upper, vertex(t, 1), c);
          for (unsigned int layer = 0; layer < 3; ++layer)
            component[i + layer * n_face_vertices] = c;
        }

    const auto                  element    = elements.element(lower);
    const Tensor<1, dim>        extent     = internal::box_extent<dim>(element);
    const double                h          = extent[direction];
    const std::array<double, 3> difference = {{-1. / h, 2. / h, -1. / h}};
    // The Q1 mass matrix of the face, a product over its directions.
    FullMatrix<double> face_mass(n_face_vertices, n_face_vertices);
    for (unsigned int t = 0; t < n_face_vertices; ++t)
      for (unsigned int u = 0; u < n_face_vertices; ++u)
        {
          double mass = 1;
          for (unsigned int j = 0, d = 0; d < dim; ++d)
            if (d != direction)
              {
                const bool same = ((t >> j) & 1) == ((u >> j) & 1);
                mass *= extent[d] * (same ? 1. / 3 : 1. / 6);
                ++j;
              }
          face_mass(t, u) = mass;
        }
    matrix.reinit(n, n);
    schur.reinit(n, n);
    for (unsigned int c = 0; c < n_components; ++c)
      for (unsigned int a = 0; a < 3; ++a)
        for (unsigned int b = 0; b < 3; ++b)
          for (unsigned int t = 0; t < n_face_vertices; ++t)
            for (unsigned int u = 0; u < n_face_vertices; ++u)
              {
                const unsigned int i = (c * 3 + a) * n_face_vertices + t;
                const unsigned int j = (c * 3 + b) * n_face_vertices + u;
                const double       value =
                  difference[a] * difference[b] * face_mass(t, u);
                if (c < dim)
                  matrix(i, j) = weights.velocity * value;
                else
                  {
                    matrix(i, j) = -weights.pressure * value;
                    schur(i, j)  = weights.schur * value;
                  }
              }
  }

  template <int dim>
  void
  GhostPenalty<dim>::compute(const Weights &weights)
  {
    // Each dof belongs to one component: the jump of its normal derivative
    // is a scalar, and dofs of different components do not couple.
    const unsigned int n_interface =
      interface_values.n_current_interface_dofs();
    const unsigned int n = element_dofs.size();
    matrix.reinit(n, n);
    schur.reinit(n, n);
    jump.resize(n);
    for (const unsigned int q : interface_values.quadrature_point_indices())
      {
        const Tensor<1, dim> normal = interface_values.normal(q);
        std::fill(jump.begin(), jump.end(), 0.);
        for (unsigned int k = 0; k < n_interface; ++k)
          {
            const double jump_k = interface_values.jump_in_shape_gradients(
                                    k,
                                    q,
                                    component[expansion[k][0].first]) *
                                  normal;
            for (const auto &[i, weight] : expansion[k])
              jump[i] += weight * jump_k;
          }
        const double JxW = interface_values.JxW(q);
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < n; ++j)
            if (component[i] == component[j])
              {
                if (component[i] < dim)
                  matrix(i, j) += weights.velocity * jump[i] * jump[j] * JxW;
                else
                  {
                    matrix(i, j) -= weights.pressure * jump[i] * jump[j] * JxW;
                    schur(i, j) += weights.schur * jump[i] * jump[j] * JxW;
                  }
              }
      }
  }

  template class GhostPenalty<2>;
  template class GhostPenalty<3>;
} // namespace vefs
