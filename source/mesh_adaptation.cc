#include <deal.II/distributed/solution_transfer.h>

#include <vefs/mesh_adaptation.h>

namespace vefs
{
  MeshLevels::MeshLevels(const Parameters &parameters)
    : min_level(parameters.min_level)
    , bulk_level(parameters.bulk_level)
    , max_level(parameters.max_level)
    , band_width(parameters.band_width)
  {
    finest_cell_size = std::numeric_limits<double>::max();
    for (unsigned int d = 0; d < parameters.dimension; ++d)
      finest_cell_size =
        std::min(finest_cell_size,
                 (parameters.cavity_upper[d] - parameters.cavity_lower[d]) /
                   parameters.coarse_subdivisions[d] / (1u << max_level));
    expect_cfl(parameters.target_cfl);
  }

  void
  MeshLevels::expect_cfl(const double cfl)
  {
    // The surface moves up to CFL finest cells per step: the band must be
    // wider than that or the surface leaves the fine region.
    band_half_width =
      std::max<double>(band_width, std::ceil(cfl) + 2) * finest_cell_size;
  }

  unsigned int
  MeshLevels::target_level(const double psi_lowest,
                           const double psi_highest) const
  {
    const double distance =
      (psi_lowest <= 0 && psi_highest >= 0)
        ? 0
        : std::min(std::abs(psi_lowest), std::abs(psi_highest));
    if (distance <= band_half_width)
      return max_level;
    return psi_highest < 0 ? bulk_level : min_level;
  }

  template <int dim>
  bool
  adapt_mesh(parallel::distributed::Triangulation<dim> &triangulation,
             TransportedFields<dim>                    &fields,
             const MeshLevels                          &levels,
             const unsigned int                         max_cycles)
  {
    constexpr unsigned int c = TransportedFields<dim>::level_set_component;
    bool                   changed = false;
    for (unsigned int cycle = 0; cycle < max_cycles; ++cycle)
      {
        for (const auto &cell : fields.dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              double lowest  = std::numeric_limits<double>::max();
              double highest = -lowest;
              for (const unsigned int v : cell->vertex_indices())
                {
                  const double psi =
                    fields.fields(cell->vertex_dof_index(v, c));
                  lowest  = std::min(lowest, psi);
                  highest = std::max(highest, psi);
                }
              // Remembered for the partitioner (children inherit it): the
              // flow is solved on liquid cells only.
              cell->set_material_id(lowest < 0 ? liquid_material_id : 0);
              const unsigned int target = levels.target_level(lowest, highest);
              const unsigned int level  = cell->level();
              if (level < target)
                {
                  cell->set_refine_flag();
                }
              else if (level > target)
                {
                  cell->set_coarsen_flag();
                }
            }
        // Mesh smoothing and the 2:1 balance may veto flags: stop when none
        // is left anywhere.
        triangulation.prepare_coarsening_and_refinement();
        bool flagged = false;
        for (const auto &cell : triangulation.active_cell_iterators())
          if (cell->is_locally_owned() &&
              (cell->refine_flag_set() || cell->coarsen_flag_set()))
            flagged = true;
        if (!Utilities::MPI::logical_or(flagged,
                                        triangulation.get_communicator()))
          break;

        parallel::distributed::
          SolutionTransfer<dim, typename TransportedFields<dim>::VectorType>
            transfer(fields.dof_handler);
        const std::vector<const typename TransportedFields<dim>::VectorType *>
          old_vectors = {&fields.fields, &fields.level_set_gradient};
        transfer.prepare_for_coarsening_and_refinement(old_vectors);
        triangulation.execute_coarsening_and_refinement();

        fields.setup_dofs();
        std::vector<typename TransportedFields<dim>::VectorType> transferred(2);
        for (auto &vector : transferred)
          {
            fields.initialize_vector(vector);
            vector.zero_out_ghost_values();
          }
        std::vector<typename TransportedFields<dim>::VectorType *> new_vectors =
          {&transferred[0], &transferred[1]};
        transfer.interpolate(new_vectors);
        fields.fields             = transferred[0];
        fields.level_set_gradient = transferred[1];
        fields.finalize();
        changed = true;
      }
    return changed;
  }

  template bool
  adapt_mesh<2>(parallel::distributed::Triangulation<2> &,
                TransportedFields<2> &,
                const MeshLevels &,
                const unsigned int);
  template bool
  adapt_mesh<3>(parallel::distributed::Triangulation<3> &,
                TransportedFields<3> &,
                const MeshLevels &,
                const unsigned int);
} // namespace vefs
