#ifndef vefs_stokes_cell_system_h
#define vefs_stokes_cell_system_h

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <vefs/compat/box_q1_values.h>
#include <vefs/fields/transported_fields.h>
#include <vefs/flow/flow_elements.h>
#include <vefs/flow/flow_parameters.h>
#include <vefs/stress/rheology.h>
#include <vefs/transport/liquid_domain.h>

#include <array>

namespace vefs
{
  /**
   * The weak form of the diffusion step on the liquid part of one cell
   * (doc/time_step_flow.md, step 7), Q1-Q1 with PSPG: the cell matrix
   * and right-hand side, and the two pieces of the Schur-complement
   * preconditioner (the pressure Laplacian weighted by tau/rho + tau_K, with
   * a penalty for p = 0 on the free surface, and the lumped pressure mass
   * of the whole cell divided by mu). On a cut cell the integrals run over
   * the liquid part only; the free surface needs no term of its own, zero
   * traction being the natural condition, except the optional free-surface
   * stabilisation (Kaus et al. 2010): theta tau rho |g.n| (u.n)(v.n) where
   * gravity presses the surface back, the change of hydrostatic load as the
   * surface moves by tau u.n within the step. The rheology supplies mu, k and
   * the advected stress terms. Used by the assembly and by the reactions of
   * contact walls.
   *
   * The object keeps what it computed for cells at the cavity's walls: the
   * contact iterations of a step need their reactions after every solve.
   */
  template <int dim>
  class StokesCellSystem
  {
  public:
    StokesCellSystem(const FlowStepParameters     &parameters,
                     const Rheology<dim>          &rheology,
                     const FiniteElement<dim>     &flow_fe,
                     const TransportedFields<dim> &fields,
                     const LiquidDomain<dim>      &domain,
                     const FlowElements<dim>      &elements,
                     const double                  tau);

    /**
     * Compute the members below for the @p cell, which holds liquid, or
     * recall them if this object computed them before (cells at the
     * boundary only).
     */
    void
    compute(const typename DoFHandler<dim>::active_cell_iterator &cell);

    FullMatrix<double> matrix;
    Vector<double>     rhs;
    FullMatrix<double> schur;
    /** The lumped pressure mass of the liquid part, divided by mu; without
     * the floor of its flow element (apply_pressure_mass_floor()). */
    Vector<double> pressure_mass;
    /** tau/rho + tau_K of the cell, the weight of the Schur Laplacian. */
    double schur_weight = 0;

    /** Weight of the penalty for p = 0 on the free surface, times
     * schur_weight / h. */
    static constexpr double surface_penalty = 10;

    /**
     * The smallest lumped pressure mass of a cut cell's vertex, as a
     * fraction of the whole cell's (measured: 0.05 and 0.1 alike, 0.5
     * costs iterations, 0 a few hundred in some steps).
     */
    static constexpr double min_pressure_mass_fraction = 0.1;

    /**
     * Raise the lumped pressure mass of each vertex of an element (a cell,
     * or a parent whose children's masses were summed) to
     * min_pressure_mass_fraction of the element's @p element_measure per
     * vertex. With the floor on each child instead, a parent's vertex next
     * to dry children kept a mass near zero, and mu M_p^-1 of the Schur
     * preconditioner grew large there (3D ball, 2.5 mm, first step: 37
     * Krylov iterations instead of 22).
     */
    void
    apply_pressure_mass_floor(Vector<double> &element_pressure_mass,
                              const double    element_measure) const;

  private:
    /**
     * What compute() keeps of a cell; of the Schur matrix the pressure
     * block, the rest being zero.
     */
    struct KeptCell
    {
      FullMatrix<double> matrix;
      Vector<double>     rhs;
      FullMatrix<double> pressure_schur;
      Vector<double>     pressure_mass;
      double             schur_weight;
    };

    void
    compute_anew(const typename DoFHandler<dim>::active_cell_iterator &cell);

    void
    keep(const typename DoFHandler<dim>::active_cell_iterator &cell);

    void
    recall(const KeptCell &kept_cell);

    /**
     * In the Schur preconditioner the pressure vanishes on an open wall as
     * on the free surface.
     */
    void
    add_open_wall_terms(
      const typename DoFHandler<dim>::active_cell_iterator &cell,
      const double                                          h);

    /**
     * u*, sigma* and div sigma* (and grad u* for 'Stress theta' < 1) at the
     * quadrature points of @p values from the vertex values of the
     * transported fields on @p transport_cell.
     */
    void
    evaluate_advected_fields(
      const BoxCellValues<dim>                             &values,
      const typename DoFHandler<dim>::active_cell_iterator &transport_cell);

    /**
     * The lumped mass, moving with u*, of the fraction of the whole cell
     * that a cut cell's liquid part lacks to 'Solver/Small cut cell mass'.
     */
    void
    add_small_cut_cell_mass(
      const typename DoFHandler<dim>::active_cell_iterator &cell,
      const double                                          mass_factor);

    /**
     * The terms on the free surface of a cut cell: the p = 0 penalty of the
     * Schur preconditioner and the free-surface stabilisation.
     */
    void
    add_surface_terms(
      const typename DoFHandler<dim>::active_cell_iterator &cell,
      const double                                          h);

    const FlowStepParameters      parameters;
    const Rheology<dim>          &rheology;
    const TransportedFields<dim> &fields;
    const LiquidDomain<dim>      &domain;
    const FlowElements<dim>      &elements;
    const FiniteElement<dim>     &flow_fe;
    const double                  tau;
    /**
     * The step of the mass term: w tau, w the weight of the new forces (1,
     * or about 1/2 with the second-order scheme, whose momentum equation
     * (rho / (w tau)) (u - u*) = F^{n+1} + ((1 - w) / w) rho a*:
     * FlowStepParameters::new_force_weight; doc/time_step_flow.md).
     */
    const double mass_tau;
    /** (1 - w) tau, the step of the old forces rho a* (0: none). */
    const double old_force_step;
    const double mu;
    /** The factors of sigma* and of (grad u sigma*) (Rheology). */
    const double sigma_star_factor;
    const double geometric_factor;
    /** Whether the stress law also sees u* ('Stress theta' < 1). */
    const bool     with_explicit_strain;
    Tensor<1, dim> gravity;
    double         regularization;

    LiquidValues<dim>     liquid_values;
    BoxSurfaceValues<dim> surface_values;

    FEFaceValues<dim> face_values;

    /** Kept cells, and their place there by active cell index. */
    std::vector<KeptCell>     kept_cells;
    std::vector<unsigned int> kept_index;
    /** The dofs of the pressure, in the cell's order. */
    std::vector<unsigned int> pressure_dofs;

    std::vector<unsigned int> component;
    /** The vertex of each dof (FE_Q(1) in every component). */
    std::vector<unsigned int>   vertex;
    std::vector<Tensor<1, dim>> u_star;
    /** u* (with the old forces) at the vertices. */
    std::vector<Tensor<1, dim>>          u_star_at_vertex;
    std::vector<SymmetricTensor<2, dim>> sigma_star;
    std::vector<Tensor<1, dim>>          div_sigma_star;
    std::vector<Tensor<2, dim>>          grad_u_star;
    /** The dof of each component (velocity, then pressure) and vertex. */
    std::array<std::array<unsigned int, GeometryInfo<dim>::vertices_per_cell>,
               dim + 1>
      dof_of;
    /** sigma* grad N of each vertex at one quadrature point. */
    std::array<Tensor<1, dim>, GeometryInfo<dim>::vertices_per_cell>
      sigma_gradient;
  };
} // namespace vefs

#endif
