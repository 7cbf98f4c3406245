#include <vefs/vertex_hanging_nodes.h>

namespace vefs
{
  namespace
  {
    /**
     * Constrain, in each component, the vertex @p middle_vertex of the child
     * @p middle_child of @p object (a refined edge: its midpoint; a refined
     * face: its centre) to the mean of @p object's own vertices.
     */
    template <typename ObjectIterator>
    void
    constrain_middle(const ObjectIterator      &object,
                     const unsigned int         middle_child,
                     const unsigned int         middle_vertex,
                     const unsigned int         n_components,
                     const std::vector<bool>   &vertex_is_relevant,
                     const IndexSet            &relevant_dofs,
                     AffineConstraints<double> &constraints)
    {
      const auto child = object->child(middle_child);
      if (!vertex_is_relevant[child->vertex_index(middle_vertex)])
        return;
      const unsigned int n_vertices = object->n_vertices();
      for (unsigned int c = 0; c < n_components; ++c)
        {
          const types::global_dof_index dof =
            child->vertex_dof_index(middle_vertex, c);
          if (!relevant_dofs.is_element(dof) || constraints.is_constrained(dof))
            continue;
          constraints.add_line(dof);
          for (unsigned int v = 0; v < n_vertices; ++v)
            constraints.add_entry(dof,
                                  object->vertex_dof_index(v, c),
                                  1. / n_vertices);
        }
    }
  } // namespace

  template <int dim>
  void
  make_vertex_hanging_node_constraints(const DoFHandler<dim>     &dof_handler,
                                       const IndexSet            &relevant_dofs,
                                       AffineConstraints<double> &constraints)
  {
    const unsigned int n_components = dof_handler.get_fe().n_dofs_per_vertex();
    Assert(dof_handler.get_fe().n_dofs_per_cell() ==
             GeometryInfo<dim>::vertices_per_cell * n_components,
           ExcMessage("Vertex degrees of freedom only (FE_Q(1)^n)."));
    // The degrees of freedom of a vertex that only artificial cells share
    // hold no valid numbers (nor always numbers::invalid_dof_index).
    std::vector<bool> vertex_is_relevant(
      dof_handler.get_triangulation().n_vertices(),
      false);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (!cell->is_artificial())
        for (const unsigned int v : cell->vertex_indices())
          vertex_is_relevant[cell->vertex_index(v)] = true;

    for (const auto &cell : dof_handler.active_cell_iterators())
      if (!cell->is_artificial())
        {
          // A refined edge: its midpoint is vertex 1 of its first child.
          for (unsigned int l = 0; l < GeometryInfo<dim>::lines_per_cell; ++l)
            if (cell->line(l)->has_children())
              constrain_middle(cell->line(l),
                               0,
                               1,
                               n_components,
                               vertex_is_relevant,
                               relevant_dofs,
                               constraints);
          // A refined face (3D): its centre is the last vertex of its first
          // child.
          if constexpr (dim == 3)
            for (const unsigned int f : cell->face_indices())
              if (cell->face(f)->has_children())
                constrain_middle(cell->face(f),
                                 0,
                                 3,
                                 n_components,
                                 vertex_is_relevant,
                                 relevant_dofs,
                                 constraints);
        }
  }

  template void
  make_vertex_hanging_node_constraints<2>(const DoFHandler<2> &,
                                          const IndexSet &,
                                          AffineConstraints<double> &);
  template void
  make_vertex_hanging_node_constraints<3>(const DoFHandler<3> &,
                                          const IndexSet &,
                                          AffineConstraints<double> &);
} // namespace vefs
