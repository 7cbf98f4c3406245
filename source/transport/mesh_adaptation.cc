#include <deal.II/base/array_view.h>
#include <deal.II/base/utilities.h>

#include <vefs/base/parameter_entries.h>
#include <vefs/compat/box_q1_values.h>
#include <vefs/fields/vertex_field_transfer.h>
#include <vefs/transport/field_hermite.h>
#include <vefs/transport/mesh_adaptation.h>
#include <vefs/transport/subtree_partition.h>

#include <array>
#include <functional>
#include <numeric>

namespace vefs
{
  void
  MeshParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh refinement");
    {
      prm.add_parameter("Minimum level",
                        min_level,
                        "Refinement level of the empty part of the cavity.",
                        Patterns::Integer(0, 20));
      prm.add_parameter("Bulk level",
                        bulk_level,
                        "Refinement level of the liquid away from its free "
                        "surface.",
                        Patterns::Integer(0, 20));
      prm.add_parameter("Maximum level",
                        max_level,
                        "Refinement level in the band around the free "
                        "surface.",
                        Patterns::Integer(0, 20));
      add_number_or_automatic(
        prm,
        "Mesh refinement",
        "Band width",
        band_width,
        automatic_band_width,
        1,
        "Half width of the finest band around the free surface, in finest "
        "cells. With 'Band placement = widened' the band is widened to CFL + "
        "2 cells (the target CFL, or the CFL number of the last step if "
        "larger) so that the surface cannot leave it within a step. "
        "Distances are estimated as psi / |grad psi| where the level set is "
        "steeper than a distance. automatic: 4 with 'widened', 2 with the "
        "predicted placements (3D ball at 6.25 mm: 200 s and 47,284 cells "
        "against 243 s and 58,568 cells with 4, the same events; with 1 the "
        "surface left the band at the impact; doc/"
        "bouncing_ball_3d_study.md).");
      add_selection(
        prm,
        "Band placement",
        band_placement,
        std::vector<std::pair<std::string, BandPlacement>>{
          {"automatic", BandPlacement::automatic},
          {"widened", BandPlacement::widened},
          {"predicted", BandPlacement::predicted},
          {"predicted, one change", BandPlacement::predicted_one_change}},
        "How the band of finest cells keeps up with a moving surface. "
        "widened: the band is widened by the CFL number, as 'Band width' "
        "says, and the mesh is adapted once per step, after the advection. "
        "predicted: before each advection the level set is traced along the "
        "characteristics on the present mesh (a prediction of where the "
        "surface will be) and the mesh is refined around the present and the "
        "predicted surface; the band stays 'Band width' cells wide at any "
        "CFL number, so large steps no longer fill the mesh with fine cells, "
        "at the cost of one more trace and a few more adaptation cycles per "
        "step. Cells within a step's local motion of the predicted surface "
        "(and two finest cells more) are brought one level below the finest, "
        "so that the next step's refinement takes one cycle there. "
        "predicted, one change: as predicted, but the change before the "
        "advection also coarsens the band of the present surface, which "
        "the next mesh change would otherwise coarsen after the advection: "
        "the advection reads the coarsened cells' fields at their former "
        "children's vertices (kept for it), and the mesh changes once per "
        "step instead of twice, again after the advection only where the "
        "surface left the finest cells. Needs linear interpolation at the "
        "feet ('Transport/Level set interpolation', 'Velocity interpolation' and 'Stress interpolation'). "
        "Both predicted placements need 'Transport/Remap distance = 0'. "
        "automatic: 'predicted, one change' where 'Time/Strain bound = "
        "local' keeps the steps through impacts without 'Time/Target CFL' "
        "(the CFL number then reaches tens of finest cells: the widened band "
        "filled the mesh of the 3D ball at 2.5 mm and stopped it; at 6.25 mm "
        "the predicted band took 200 s against 217 s; the 2D ball of "
        "tests/bouncing_ball_2d_local.prm to 1.35 s 3.1 s against 4.1 s, "
        "its lowest centroid within 0.2 mm; doc/"
        "bouncing_ball_3d_study.md) and the feet allow it, 'widened' "
        "otherwise (at small CFL numbers the prediction costs more than it "
        "saves: 34 s against 31 s for the 3D ball at 12.5 mm).");
      add_number_or_automatic(
        prm,
        "Mesh refinement",
        "Band miss tolerance",
        band_miss_tolerance,
        automatic_band_miss_tolerance,
        0,
        "With 'Band placement = predicted, one change': the fraction (at "
        "most 1) of the cells the surface crosses that may be coarser than "
        "the finest level (the surface left the band there) before the mesh "
        "changes again: the predicted surface after a cycle of the "
        "refinement ahead of it, the surface after the advection. Each "
        "change rebuilds the whole mesh; up to this fraction, the advection "
        "and the flow step use those cells on their coarser level and the "
        "next step's change before the advection refines them. 0: the mesh "
        "changes whenever one cell is left coarse. automatic: 0.001 with "
        "'predicted, one change' (3D ball at 2.5 mm: half the time of the "
        "adaptation after the advection, the same events; "
        "doc/bouncing_ball_3d_study.md), 0 otherwise.");
    }
    prm.leave_subsection();
  }

  void
  MeshParameters::resolve(const bool steps_fixed_and_feet_linear)
  {
    if (band_placement == BandPlacement::automatic)
      band_placement = steps_fixed_and_feet_linear
                         ? BandPlacement::predicted_one_change
                         : BandPlacement::widened;
    if (automatic_band_width)
      band_width = band_predicted() ? 2 : 4;
    if (automatic_band_miss_tolerance)
      band_miss_tolerance = band_in_one_change() ? 0.001 : 0;
  }

  void
  MeshParameters::check() const
  {
    require(band_miss_tolerance <= 1,
            "Mesh refinement/Band miss tolerance",
            "is a fraction of the surface's cells: 'automatic' or a number "
            "from 0 to 1");
    require(band_miss_tolerance == 0 || band_in_one_change(),
            "Mesh refinement/Band miss tolerance",
            "applies to 'Band placement = predicted, one change' only (the "
            "other placements adapt the mesh after every advection): leave "
            "it 0 or choose that placement");
    require(min_level <= bulk_level && bulk_level <= max_level,
            "Mesh refinement/Bulk level",
            "levels must satisfy Minimum level <= Bulk level <= Maximum "
            "level");
  }

  MeshLevels::MeshLevels(const MeshParameters   &parameters,
                         const CavityParameters &cavity,
                         const unsigned int      dimension,
                         const double            target_cfl)
    : min_level(parameters.min_level)
    , bulk_level(parameters.bulk_level)
    , max_level(parameters.max_level)
    , band_width(parameters.band_width)
    , band_predicted(parameters.band_predicted())
  {
    finest_cell_size = cavity.cell_size(dimension, max_level);
    expect_cfl(target_cfl);
  }

  void
  MeshLevels::expect_cfl(const double cfl)
  {
    // The surface moves up to CFL finest cells per step: the band must be
    // wider than that or the surface leaves the fine region. Refined ahead of
    // the surface, the band keeps its width.
    reach_half_width =
      std::max<double>(band_width, std::ceil(cfl) + 2) * finest_cell_size;
    band_half_width =
      band_predicted ? band_width * finest_cell_size : reach_half_width;
  }

  unsigned int
  MeshLevels::target_level(const CellLevelSet &psi, const double reach) const
  {
    const double distance =
      (psi.lowest <= 0 && psi.highest >= 0)
        ? 0
        : std::min(std::abs(psi.lowest), std::abs(psi.highest)) /
            std::max(1., psi.slope);
    const unsigned int away = psi.highest < 0 ? bulk_level : min_level;
    if (distance <= band_half_width)
      return max_level;
    if (distance <= reach)
      return std::max(away, std::max(max_level, 1u) - 1);
    return away;
  }

  std::pair<unsigned int, unsigned int>
  MeshLevels::allowed_levels(const CellLevelSet &present) const
  {
    if (!band_predicted)
      {
        const unsigned int target = target_level(present, reach_half_width);
        return {target, target};
      }
    return {target_level(present, band_half_width),
            target_level(present, reach_half_width)};
  }

  std::pair<unsigned int, unsigned int>
  MeshLevels::allowed_levels(const CellLevelSet &present,
                             const CellLevelSet &ahead,
                             const double        motion) const
  {
    const unsigned int target = std::max(target_level(present, band_half_width),
                                         allowed_levels(ahead, motion).first);
    return {target, target};
  }

  std::pair<unsigned int, unsigned int>
  MeshLevels::allowed_levels(const CellLevelSet &ahead,
                             const double        motion) const
  {
    const double halo =
      std::max(motion + 2 * finest_cell_size, band_half_width);
    const unsigned int target = target_level(ahead, halo);
    return {target, target};
  }

  namespace
  {
    /**
     * The length of the gradient of the Q1 level set at the center of an
     * axis-parallel @p cell.
     */
    template <int dim>
    double
    level_set_slope(
      const TransportedFields<dim>                         &fields,
      const typename TransportedFields<dim>::VectorType    &level_set,
      const typename DoFHandler<dim>::active_cell_iterator &cell)
    {
      constexpr unsigned int c = TransportedFields<dim>::level_set_component;
      Point<dim>             center;
      for (unsigned int d = 0; d < dim; ++d)
        center[d] = 0.5;
      const Tensor<1, dim> extent = internal::box_extent<dim>(cell);
      Tensor<1, dim>       gradient;
      for (const unsigned int v : cell->vertex_indices())
        for (unsigned int d = 0; d < dim; ++d)
          gradient[d] += fields.entry_at(level_set, cell, v, c) *
                         internal::q1_shape(v, center, d) / extent[d];
      return gradient.norm();
    }

    /** The level set slot of @p level_set on @p cell. */
    template <int dim>
    MeshLevels::CellLevelSet
    cell_level_set(const TransportedFields<dim>                      &fields,
                   const typename TransportedFields<dim>::VectorType &level_set,
                   const typename DoFHandler<dim>::active_cell_iterator &cell)
    {
      constexpr unsigned int   c = TransportedFields<dim>::level_set_component;
      MeshLevels::CellLevelSet psi{std::numeric_limits<double>::max(),
                                   -std::numeric_limits<double>::max(),
                                   level_set_slope<dim>(fields,
                                                        level_set,
                                                        cell)};
      for (const unsigned int v : cell->vertex_indices())
        {
          const double value = fields.entry_at(level_set, cell, v, c);
          psi.lowest         = std::min(psi.lowest, value);
          psi.highest        = std::max(psi.highest, value);
        }
      return psi;
    }

    /**
     * How far the surface moves at @p cell in the coming step: the largest
     * change of the level set from @p psi to @p psi_ahead at its vertices.
     */
    template <int dim>
    double
    local_motion(const TransportedFields<dim>                      &fields,
                 const typename TransportedFields<dim>::VectorType &psi,
                 const typename TransportedFields<dim>::VectorType &psi_ahead,
                 const typename DoFHandler<dim>::active_cell_iterator &cell)
    {
      constexpr unsigned int c = TransportedFields<dim>::level_set_component;
      double                 motion = 0;
      for (const unsigned int v : cell->vertex_indices())
        {
          motion = std::max(motion,
                            std::abs(fields.entry_at(psi_ahead, cell, v, c) -
                                     fields.entry_at(psi, cell, v, c)));
        }
      return motion;
    }

    /**
     * The gradient-augmented level set at the new vertices of refined cells.
     * VertexFieldTransfer interpolates the Q1 field there, and where psi is
     * convex (across a thin filament, between two surfaces) that raises it:
     * the liquid shrinks by O(h^2) at each refinement (vortex, h = 1/128,
     * CFL 1, no volume correction: 8.9 % of the liquid lost with the Q1
     * values, 5.2 % with the cubic ones, 1.7 % gained on a uniform mesh).
     * Each cell to be refined packs the value and gradient of its Hermite
     * interpolant at the vertices of its children, which take them.
     * The fields are slot 0 of the transfer, the level set gradient slot 1.
     */
    template <int dim>
    class HermiteRefinement : public VertexFieldTransfer<dim>::LatticeSource
    {
    public:
      HermiteRefinement(const TransportedFields<dim> &fields,
                        const LevelSetGradient<dim>  &level_set_gradient)
        : fields(fields)
      {
        hermite.recover(fields, &level_set_gradient);
      }

      std::vector<std::pair<unsigned int, unsigned int>>
      components() const override
      {
        std::vector<std::pair<unsigned int, unsigned int>> result = {
          {0, TransportedFields<dim>::level_set_component}};
        for (unsigned int d = 0; d < dim; ++d)
          result.emplace_back(1, d);
        return result;
      }

      /** Value and gradient at each lattice point of a cell to be refined. */
      std::vector<double>
      pack(const typename Triangulation<dim>::cell_iterator &cell,
           const typename Triangulation<dim>::CellStatus status) const override
      {
        if (status != Triangulation<dim>::CELL_REFINE)
          return {};
        std::vector<double> values((dim + 1) * FamilyLattice<dim>::n_points);
        const auto          dof_cell = fields.cell_of(cell);
        const auto          entries  = fields.vertex_entries(dof_cell);
        // The new vertices take the cubic itself: clipping it to the
        // parent's nodal range would cut the filaments the carried gradient
        // keeps.
        constexpr bool limited = false;
        for (unsigned int i = 0; i < FamilyLattice<dim>::n_points; ++i)
          {
            Tensor<1, dim> gradient;
            values[(dim + 1) * i] =
              hermite.value(fields,
                            dof_cell,
                            entries,
                            FamilyLattice<dim>::unit_point(i),
                            limited,
                            &gradient);
            for (unsigned int d = 0; d < dim; ++d)
              values[(dim + 1) * i + 1 + d] = gradient[d];
          }
        return values;
      }

    private:
      const TransportedFields<dim> &fields;
      FieldHermite<dim>             hermite;
    };
  } // namespace

  template <int dim>
  bool
  adapt_mesh(parallel::distributed::Triangulation<dim>   &triangulation,
             TransportedFields<dim>                      &fields,
             LevelSetGradient<dim>                       *level_set_gradient,
             const MeshLevels                            &levels,
             const LevelSetInterpolation                  interpolation,
             typename TransportedFields<dim>::VectorType *surface_ahead,
             const PresentBand                            present_band,
             CoarsenedDetail<dim>                        *coarsened_detail)
  {
    Assert(present_band != PresentBand::coarsened || coarsened_detail,
           ExcMessage("A coarsened band keeps its detail."));
    constexpr unsigned int c = TransportedFields<dim>::level_set_component;
    for (const auto &cell : fields.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const auto present =
            cell_level_set<dim>(fields, fields.vector(), cell);
          std::pair<unsigned int, unsigned int> allowed;
          double                                lowest = present.lowest;
          if (!surface_ahead)
            allowed = levels.allowed_levels(present);
          else
            {
              const auto ahead =
                cell_level_set<dim>(fields, *surface_ahead, cell);
              const double motion = local_motion<dim>(fields,
                                                      fields.vector(),
                                                      *surface_ahead,
                                                      cell);
              allowed             = present_band == PresentBand::kept
                                      ? levels.allowed_levels(present, ahead, motion)
                                      : levels.allowed_levels(ahead, motion);
              lowest              = ahead.lowest;
            }
          // Liquid cells (a vertex with psi < 0) are remembered for the
          // partitioner (children inherit it): the flow is solved on
          // them only, after the advection, so with a predicted surface
          // its liquid counts.
          cell->set_material_id(lowest < 0 ? liquid_material_id : 0);
          const unsigned int level = cell->level();
          if (level < allowed.first)
            {
              cell->set_refine_flag();
            }
          else if (level > allowed.second &&
                   present_band != PresentBand::refine_only)
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
    if (!Utilities::MPI::logical_or(flagged, triangulation.get_communicator()))
      return false;

    // The level set gradient has dim used slots, the predicted surface
    // one. Only the gradient-augmented interpolation reads the gradient:
    // with the linear one it is not carried (a fifth of the data sent in
    // 3D).
    using Transfer = VertexFieldTransfer<dim>;
    const bool with_gradient =
      level_set_gradient &&
      interpolation == LevelSetInterpolation::gradient_augmented;
    std::vector<unsigned int> all_fields(fields.n_components);
    std::iota(all_fields.begin(), all_fields.end(), 0);
    std::vector<unsigned int> gradient(dim);
    std::iota(gradient.begin(), gradient.end(), 0);
    std::vector<typename Transfer::Slot> slots = {
      {&fields.vector(), all_fields}};
    if (with_gradient)
      slots.push_back({&level_set_gradient->vector(), gradient});
    if (surface_ahead)
      slots.push_back({surface_ahead, {c}});
    // Refined cells take the gradient-augmented level set, or the detail
    // they kept (the one-change band refuses it).
    std::unique_ptr<HermiteRefinement<dim>> hermite_refinement;
    typename Transfer::LatticeSource       *lattice_source = nullptr;
    if (with_gradient)
      {
        hermite_refinement =
          std::make_unique<HermiteRefinement<dim>>(fields, *level_set_gradient);
        lattice_source = hermite_refinement.get();
      }
    if (coarsened_detail && present_band != PresentBand::kept)
      {
        AssertThrow(!lattice_source, ExcInternalError());
        coarsened_detail->from_fields(fields);
        lattice_source = coarsened_detail;
      }
    const auto move_fields = [&](const std::function<void()> &change) {
      auto transferred = carry_through_mesh_change(triangulation,
                                                   fields,
                                                   slots,
                                                   change,
                                                   lattice_source);
      // swap(), not operator=: a vector whose owned range is the same
      // after the change would keep its old ghost layout.
      fields.swap(transferred[0]);
      if (with_gradient)
        level_set_gradient->swap(transferred[1]);
      else if (level_set_gradient)
        level_set_gradient->reinit(fields);
      if (surface_ahead)
        {
          surface_ahead->swap(transferred.back());
          fields.make_consistent(*surface_ahead);
        }
      fields.finalize();
      if (with_gradient)
        level_set_gradient->finalize(fields);
    };
    move_fields([&]() { triangulation.execute_coarsening_and_refinement(); });
    // Refined last cells of subtrees that must stay whole weigh as much
    // each as the subtree: p4est may have cut one (SubtreePartition).
    if (subtrees_split(triangulation, levels.subtree_level))
      move_fields([&]() { triangulation.repartition(); });
    return true;
  }

  template <int dim>
  SurfaceCells
  count_surface_cells(const TransportedFields<dim> &fields,
                      const unsigned int            max_level)
  {
    return count_surface_cells(fields, fields.vector(), max_level);
  }

  template <int dim>
  SurfaceCells
  count_surface_cells(
    const TransportedFields<dim>                      &fields,
    const typename TransportedFields<dim>::VectorType &level_set,
    const unsigned int                                 max_level)
  {
    SurfaceCells count;
    for (const auto &cell : fields.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && fields.surface_crosses(level_set, cell))
        {
          ++count.total;
          if (static_cast<unsigned int>(cell->level()) < max_level)
            ++count.coarse;
        }
    // Both counts in one reduction: it runs at every refinement cycle.
    std::array<unsigned int, 2> counts = {{count.coarse, count.total}};
    Utilities::MPI::sum(
      ArrayView<const unsigned int>(counts.data(), counts.size()),
      fields.dof_handler.get_triangulation().get_communicator(),
      ArrayView<unsigned int>(counts.data(), counts.size()));
    return {counts[0], counts[1]};
  }

  template <int dim>
  unsigned int
  refine_ahead_of_surface(
    parallel::distributed::Triangulation<dim>   &triangulation,
    TransportedFields<dim>                      &fields,
    LevelSetGradient<dim>                       &level_set_gradient,
    const MeshLevels                            &levels,
    const unsigned int                           max_cycles,
    const LevelSetInterpolation                  interpolation,
    typename TransportedFields<dim>::VectorType &surface_ahead,
    const bool                                   coarsen_present_band,
    const double                                 miss_tolerance,
    CoarsenedDetail<dim>                        &coarsened_detail)
  {
    // The halo makes one cycle enough unless the surface moves farther than
    // the last step's: more cycles then, until the predicted surface lies
    // in finest cells. Each cycle rebuilds and transfers the whole mesh, so
    // none is spent on a few cells left coarse (the 1.25 mm ball after its
    // impact: 24-51 of 230,000 left at 2.5 mm, a second cycle 13-17 s of a
    // 72-100 s step).
    unsigned int changes = 0;
    for (unsigned int cycle = 0; cycle < max_cycles; ++cycle)
      {
        const PresentBand present_band =
          !coarsen_present_band ? PresentBand::kept
          : cycle == 0          ? PresentBand::coarsened
                                : PresentBand::refine_only;
        if (!adapt_mesh(triangulation,
                        fields,
                        &level_set_gradient,
                        levels,
                        interpolation,
                        &surface_ahead,
                        present_band,
                        &coarsened_detail))
          break;
        ++changes;
        if (count_surface_cells(fields, surface_ahead, levels.max_level)
              .within(miss_tolerance))
          break;
      }
    if (coarsen_present_band)
      coarsened_detail.update_ghosts(triangulation);
    return changes;
  }

  template bool
  adapt_mesh<2>(parallel::distributed::Triangulation<2> &,
                TransportedFields<2> &,
                LevelSetGradient<2> *,
                const MeshLevels &,
                const LevelSetInterpolation,
                TransportedFields<2>::VectorType *,
                const PresentBand,
                CoarsenedDetail<2> *);
  template bool
  adapt_mesh<3>(parallel::distributed::Triangulation<3> &,
                TransportedFields<3> &,
                LevelSetGradient<3> *,
                const MeshLevels &,
                const LevelSetInterpolation,
                TransportedFields<3>::VectorType *,
                const PresentBand,
                CoarsenedDetail<3> *);

  template SurfaceCells
  count_surface_cells<2>(const TransportedFields<2> &, const unsigned int);
  template SurfaceCells
  count_surface_cells<3>(const TransportedFields<3> &, const unsigned int);

  template unsigned int
  refine_ahead_of_surface<2>(parallel::distributed::Triangulation<2> &,
                             TransportedFields<2> &,
                             LevelSetGradient<2> &,
                             const MeshLevels &,
                             const unsigned int,
                             const LevelSetInterpolation,
                             TransportedFields<2>::VectorType &,
                             const bool,
                             const double,
                             CoarsenedDetail<2> &);
  template unsigned int
  refine_ahead_of_surface<3>(parallel::distributed::Triangulation<3> &,
                             TransportedFields<3> &,
                             LevelSetGradient<3> &,
                             const MeshLevels &,
                             const unsigned int,
                             const LevelSetInterpolation,
                             TransportedFields<3>::VectorType &,
                             const bool,
                             const double,
                             CoarsenedDetail<3> &);
} // namespace vefs
