#include <deal.II/base/quadrature_lib.h>

#include <vefs/ghost_penalty.h>

#include <algorithm>
#include <utility>

namespace vefs
{
  template <int dim>
  GhostPenalty<dim>::GhostPenalty(const Parameters         &parameters,
                                  const Rheology<dim>      &rheology,
                                  const FiniteElement<dim> &flow_fe,
                                  const FlowElements<dim>  &elements,
                                  const double              tau)
    : parameters(parameters)
    , tau(tau)
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
    const auto                           visit = [&](const auto        &cell,
                           const unsigned int face,
                           const unsigned int subface,
                           const auto        &neighbor,
                           const unsigned int neighbor_face,
                           const unsigned int neighbor_subface) {
      // Within one flow element (FlowElements) the normal derivatives do
      // not jump.
      const bool next_to_walls = elements.element(cell)->at_boundary() ||
                                 elements.element(neighbor)->at_boundary();
      if (!elements.has_liquid(neighbor) ||
          elements.same_element(cell, neighbor) ||
          (faces == Faces::next_to_walls && !next_to_walls))
        return;
      // A face between two cut cells is seen from both: it belongs to the
      // side with the smaller CellId, on whichever rank owns that side.
      const bool neighbor_is_cut = elements.location(neighbor) == Location::cut;
      if (neighbor_is_cut && neighbor->id() < cell->id())
        return;
      if (!matrices_wanted)
        {
          // The sparsity pattern needs only the dofs of both elements, and
          // couples each component with itself only.
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
          return;
        }
      interface_values
        .reinit(cell, face, subface, neighbor, neighbor_face, neighbor_subface);
      expand_to_elements(cell, neighbor);
      // Between two cut cells each side weighs in with half the penalty
      // and its own h.
      const Weights weights = neighbor_is_cut
                                                          ? face_weights(elements.size(cell), 0.5) +
                                    face_weights(elements.size(neighbor), 0.5)
                                                          : face_weights(elements.size(cell), 1.);
      compute(weights);
      if (keep && next_to_walls)
        keep_face(element_dofs);
      action(matrix, schur, element_dofs);
    };

    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && elements.location(cell) == Location::cut)
        for (const unsigned int f : cell->face_indices())
          {
            if (cell->at_boundary(f))
              continue;
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
    const double rho   = parameters.density;
    const double gamma = parameters.ghost_penalty * share;
    const double tau_K =
      parameters.pressure_stabilization / (rho / tau + 4 * mu / (h * h));
    return {gamma * (mu + rho * h * h / tau) * h,
            gamma * tau_K * h,
            gamma * (tau / rho + tau_K) * h};
  }

  template <int dim>
  void
  GhostPenalty<dim>::get_element_dofs(
    const typename DoFHandler<dim>::cell_iterator &cell,
    std::vector<types::global_dof_index>          &dofs) const
  {
    dofs.resize(flow_fe.n_dofs_per_cell());
    if (!elements.on_parent(cell))
      {
        cell->get_dof_indices(dofs);
        return;
      }
    for (unsigned int i = 0; i < dofs.size(); ++i)
      {
        const auto [c, v] = flow_fe.system_to_component_index(i);
        dofs[i]           = elements.parent_vertex_dof(cell, v, c);
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
    if (!elements.on_parent(cell) && !elements.on_parent(neighbor))
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
        // A dof of a side on its parent is interpolated from the parent's
        // vertices (a dof both sides share, the same way from either).
        const bool from_cell = dof_pair[0] != numbers::invalid_unsigned_int &&
                               elements.on_parent(cell);
        const bool from_neighbor =
          !from_cell && dof_pair[1] != numbers::invalid_unsigned_int &&
          elements.on_parent(neighbor);
        const auto        &side = from_neighbor ? neighbor : cell;
        const unsigned int local =
          from_neighbor                                  ? dof_pair[1]
          : dof_pair[0] != numbers::invalid_unsigned_int ? dof_pair[0]
                                                         : dof_pair[1];
        const auto [c, v] = flow_fe.system_to_component_index(local);
        expansion[k].clear();
        if (from_cell || from_neighbor)
          {
            const unsigned int child =
              side->parent()->child_iterator_to_index(side);
            for (const auto &[vertex, weight] :
                 elements.vertex_weights(child, v))
              expansion[k].emplace_back(
                index_of(elements.parent_vertex_dof(side, vertex, c), c),
                weight);
          }
        else
          expansion[k].emplace_back(index_of(interface_dofs[k], c), 1.);
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
