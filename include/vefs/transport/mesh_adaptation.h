#ifndef vefs_mesh_adaptation_h
#define vefs_mesh_adaptation_h

#include <deal.II/base/parameter_handler.h>

#include <vefs/base/cavity.h>
#include <vefs/fields/coarsened_detail.h>
#include <vefs/fields/transported_fields.h>
#include <vefs/transport/level_set_gradient.h>
#include <vefs/transport/transport_parameters.h>

namespace vefs
{
  /** How the band of finest cells keeps up with a moving surface. */
  enum class BandPlacement
  {
    /** As the steps and the feet allow: MeshParameters::resolve(). */
    automatic,
    /** Widened by the CFL number; the mesh adapted after the advection. */
    widened,
    /** Refined ahead of the surface the characteristics predict. */
    predicted,
    /** The same, the present band coarsened in that one change. */
    predicted_one_change
  };

  /**
   * The refinement levels and the band of finest cells around the surface:
   * subsection "Mesh refinement".
   */
  struct MeshParameters
  {
    void
    declare(dealii::ParameterHandler &prm);

    /**
     * An 'automatic' band placement becomes 'predicted, one change' where
     * @p steps_fixed_and_feet_linear (the steps are not shortened at an
     * impact, so the CFL number reaches tens of finest cells and a band
     * widened by it fills the mesh; and the feet read the Q1 fields that
     * placement keeps), 'widened' otherwise. 'automatic' band width and
     * miss tolerance then take the values measured for the placement
     * (doc/bouncing_ball_3d_study.md, "Settings of the fine scenes"): a band of
     * 2 finest cells and a miss tolerance of 0.001 for the predicted
     * placements, 4 cells (widened by the CFL number) and 0 otherwise.
     */
    void
    resolve(const bool steps_fixed_and_feet_linear);

    /** Throws InputError for levels out of order or a stray tolerance. */
    void
    check() const;

    /**
     * Whether the band is refined ahead of the surface before each advection
     * ('Band placement = predicted') instead of widened by the CFL number.
     */
    bool
    band_predicted() const
    {
      Assert(band_placement != BandPlacement::automatic,
             dealii::ExcMessage("MeshParameters::resolve() first."));
      return band_placement != BandPlacement::widened;
    }

    /**
     * Whether that change also coarsens the present band ('Band placement =
     * predicted, one change'), the coarsened cells' fields kept for the
     * advection (CoarsenedDetail, owned by the SurfaceTracker).
     */
    bool
    band_in_one_change() const
    {
      return band_placement == BandPlacement::predicted_one_change;
    }

    unsigned int  min_level            = 2;
    unsigned int  bulk_level           = 4;
    unsigned int  max_level            = 6;
    double        band_width           = 4;
    bool          automatic_band_width = true;
    BandPlacement band_placement       = BandPlacement::automatic;
    /**
     * The fraction of the surface's cells that may be left coarser than the
     * finest level after the advection before the mesh changes again then
     * ('Band miss tolerance').
     */
    double band_miss_tolerance           = 0;
    bool   automatic_band_miss_tolerance = true;
  };

  /** Material id of cells with liquid, for the weighted partitioning. */
  constexpr types::material_id liquid_material_id = 1;

  /**
   * Refinement levels tied to the free surface (doc/time_step_surface.md,
   * step 5): the finest level in a band around psi = 0, the bulk level inside
   * the liquid, the minimum level in the empty cavity.
   */
  class MeshLevels
  {
  public:
    /** @p target_cfl: 'Time/Target CFL', the first width of the band. */
    MeshLevels(const MeshParameters   &parameters,
               const CavityParameters &cavity,
               const unsigned int      dimension,
               const double            target_cfl);

    /**
     * Widen the band for steps of @p cfl finest cells (at least the
     * parameter "Band width"): the surface must not leave it in one step.
     * With 'Band placement = predicted' the band keeps its width, and @p cfl
     * says how far around the surface the adaptation after an advection
     * keeps the cells the refinement ahead made one level below the finest.
     */
    void
    expect_cfl(const double cfl);

    /** A level set on a cell: its lowest and highest nodal values, slope. */
    struct CellLevelSet
    {
      double lowest;
      double highest;
      double slope;
    };

    /**
     * The levels a cell with the level set @p present may keep: it is
     * refined below the first, coarsened above the second. Widened band:
     * the target of the surface. After an advection with 'Band placement =
     * predicted': anything from the band's target up to the halo's level
     * (one below the finest) within the CFL number's reach (expect_cfl()).
     */
    std::pair<unsigned int, unsigned int>
    allowed_levels(const CellLevelSet &present) const;

    /**
     * Refined ahead ('Band placement = predicted'): the finer of the
     * @p present surface's target (its band only) and that of the predicted
     * surface @p ahead, with a halo one level below the finest within
     * @p motion (how far the surface moves at the cell in the step) and two
     * finest cells more.
     */
    std::pair<unsigned int, unsigned int>
    allowed_levels(const CellLevelSet &present,
                   const CellLevelSet &ahead,
                   const double        motion) const;

    /** The same for the predicted surface @p ahead alone. */
    std::pair<unsigned int, unsigned int>
    allowed_levels(const CellLevelSet &ahead, const double motion) const;

    /** Size of the finest cells (their shortest edge). */
    double finest_cell_size;

    const unsigned int min_level, bulk_level, max_level;

    /**
     * Cells finer than this level stay on the rank of their ancestor on it
     * (SubtreePartition: the flow's elements two or more levels coarser
     * than the finest cells); negative: p4est's partition as it is.
     */
    int subtree_level = -1;

  private:
    /**
     * The level of a cell with the level set @p psi. Where psi has been
     * stretched (slope above 1) psi underestimates the distance to the
     * surface by that factor, and the band is measured in psi / slope.
     * Beyond the band but within @p reach of the surface: one level below
     * the finest (at least the level away from the surface).
     */
    unsigned int
    target_level(const CellLevelSet &psi, const double reach) const;

    double band_width;
    bool   band_predicted;
    /** Half width of the band of finest cells around the surface. */
    double band_half_width;
    /** How far the surface can move in a step, by the CFL number (at least
     * the band). */
    double reach_half_width;
  };

  /**
   * What a change of the mesh does with the band of the present surface:
   * before an advection ('Band placement = predicted'), and in the further
   * cycles that complete the band at a remap (SurfaceTracker).
   */
  enum class PresentBand
  {
    /** Keep it: the adaptation after the advection coarsens it. */
    kept,
    /**
     * Coarsen it in the same change; the coarsened cells keep their fields
     * for the advection in a CoarsenedDetail.
     */
    coarsened,
    /**
     * A further cycle: refine only; after 'coarsened', carrying the detail
     * along (the cycles that complete a band at a remap have none).
     */
    refine_only
  };

  /**
   * One mesh change toward the target levels (a cell moves by at most one
   * level), transferring the fields (and @p level_set_gradient, if given:
   * nullptr before it exists). Returns false, leaving the mesh as it is, if
   * no cell needs to change. In the time loop one change a step suffices:
   * the band is wider than the surface moves; the callers that need more
   * repeat it (the initial refinement, refine_ahead_of_surface(), the
   * remap's cycles in SurfaceTracker).
   * Unless @p interpolation is linear, the level set at new vertices is the
   * cubic one of the refined cell, not the Q1 one. If @p surface_ahead is
   * given (the level set the next advection will give, predict_level_set()),
   * cells take the finer of the levels the two level sets ask for, and
   * @p surface_ahead is transferred too. Ahead of the surface, the cells
   * within a step's motion of the predicted surface (|@p surface_ahead -
   * psi| at the cell, and two finest cells more) are brought one level below
   * the finest, so that the next refinement ahead takes one cycle: where the
   * surface moves slowly this halo is thin, where it moves fast as wide as
   * the motion. The adaptation after the advection then keeps such cells
   * within the CFL number's reach (MeshLevels::expect_cfl()) as they are.
   * @p present_band says whether the present surface's band is kept too;
   * if not, @p coarsened_detail keeps the coarsened cells' fields.
   */
  template <int dim>
  bool
  adapt_mesh(
    parallel::distributed::Triangulation<dim>   &triangulation,
    TransportedFields<dim>                      &fields,
    LevelSetGradient<dim>                       *level_set_gradient,
    const MeshLevels                            &levels,
    const LevelSetInterpolation                  interpolation,
    typename TransportedFields<dim>::VectorType *surface_ahead = nullptr,
    const PresentBand     present_band     = PresentBand::kept,
    CoarsenedDetail<dim> *coarsened_detail = nullptr);

  /** The cells the surface (psi = 0) crosses, over all ranks. */
  struct SurfaceCells
  {
    /** Those coarser than the finest level. */
    unsigned int coarse = 0;
    /** All of them. */
    unsigned int total = 0;

    /**
     * Whether the band kept up but for at most the fraction
     * @p miss_tolerance of the cells ('Band miss tolerance'): no mesh
     * change for the rest.
     */
    bool
    within(const double miss_tolerance) const
    {
      return coarse <= miss_tolerance * total;
    }
  };

  /**
   * The cells the surface crosses, and those of them coarser than
   * @p max_level: right after an advection, where the band of finest cells
   * did not keep up with the surface.
   */
  template <int dim>
  SurfaceCells
  count_surface_cells(const TransportedFields<dim> &fields,
                      const unsigned int            max_level);

  /** The same for the level set slot of @p level_set (layout of the fields). */
  template <int dim>
  SurfaceCells
  count_surface_cells(
    const TransportedFields<dim>                      &fields,
    const typename TransportedFields<dim>::VectorType &level_set,
    const unsigned int                                 max_level);

  /**
   * Before an advection ('Band placement = predicted'): adapt the mesh
   * toward the present surface and @p surface_ahead, the level set the
   * advection will give (predict_level_set()), one cycle at a time until
   * the predicted surface lies in cells of the finest level, but for at
   * most the fraction @p miss_tolerance of the cells it crosses ('Band miss
   * tolerance'), at most @p max_cycles times. With @p coarsen_present_band
   * the first cycle also coarsens the present band (PresentBand::coarsened),
   * keeping the coarsened cells' fields in @p coarsened_detail, whose ghost
   * cells get theirs at the end. Returns the number of mesh changes made.
   */
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
    CoarsenedDetail<dim>                        &coarsened_detail);
} // namespace vefs

#endif
