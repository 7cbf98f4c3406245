#ifndef vefs_ghost_penalty_h
#define vefs_ghost_penalty_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_interface_values.h>
#include <deal.II/lac/full_matrix.h>

#include <vefs/flow/flow_elements.h>
#include <vefs/flow/flow_parameters.h>
#include <vefs/stress/rheology.h>

#include <functional>

namespace vefs
{
  /**
   * The ghost penalty (Burman 2010) that keeps the flow step of a cut cell
   * as well posed as that of a whole one, however small its liquid part: on
   * each face between a cut cell and another cell with liquid, the jumps of
   * the normal derivatives of velocity and pressure,
   *   gamma (mu + rho h^2 / tau) h int_F [d_n u] . [d_n v]
   *   - gamma tau_K h int_F [d_n p] [d_n q],
   * and the same pressure term, weighted like the Schur Laplacian, in the
   * preconditioner. Both vanish for fields linear across the face, so a
   * liquid at rest under gravity is still exactly at rest.
   */
  template <int dim>
  class GhostPenalty
  {
  public:
    /**
     * One face: the interface matrices of the system and of the Schur
     * preconditioner, and the degrees of freedom of both cells.
     */
    using FaceAction =
      std::function<void(const FullMatrix<double>                   &matrix,
                         const FullMatrix<double>                   &schur,
                         const std::vector<types::global_dof_index> &dofs)>;

    /** Which faces for_each_face() visits. */
    enum class Faces
    {
      all,
      /** Faces with a flow element (FlowElements) at the cavity boundary
       * on either side. */
      next_to_walls
    };

    GhostPenalty(const FlowStepParameters &parameters,
                 const Rheology<dim>      &rheology,
                 const FiniteElement<dim> &flow_fe,
                 const FlowElements<dim>  &elements,
                 const double              tau);

    /**
     * Call @p action for every face of a locally owned cell whose flow
     * element (FlowElements, classified) is cut, with liquid in the element
     * on the other side, once: a face between two cut elements is visited
     * from the side with the smaller CellId (which may be on another rank;
     * the elements' CellIds where the two elements have the same size, and
     * then the whole face at once) and carries half the penalty of each
     * side; faces within an element are not visited. With
     * @p matrices_wanted false the matrices are empty and @p action is
     * called once per component with the dofs of that component on both
     * cells, sorted: for the sparsity pattern (the penalty couples each
     * component with itself only).
     * @p faces may restrict the visit to faces next to the walls.
     *
     * A first visit of all faces with matrices keeps those of the faces
     * next to the walls, and later visits of these faces replay them: one
     * object serves the assembly and the contact iterations of one time
     * step (same mesh, liquid domain and tau). Only they are kept: keeping
     * every face's took 4 % of a step of the 3D ball at 2.5 mm, and no
     * later visit wants them.
     */
    void
    for_each_face(const DoFHandler<dim> &dof_handler,
                  const bool             matrices_wanted,
                  const FaceAction      &action,
                  const Faces            faces = Faces::all);

  private:
    /** The factors of the velocity, pressure and Schur terms of a face. */
    struct Weights
    {
      double velocity;
      double pressure;
      double schur;

      Weights
      operator+(const Weights &other) const
      {
        return {velocity + other.velocity,
                pressure + other.pressure,
                schur + other.schur};
      }
    };

    /** The factors of a side of size @p h that has a @p share of the face. */
    Weights
    face_weights(const double h, const double share) const;

    /** The dofs of the flow element of @p cell (FlowElements): its own, or
     * its parent's vertices'. */
    void
    get_element_dofs(const typename DoFHandler<dim>::cell_iterator &cell,
                     std::vector<types::global_dof_index>          &dofs) const;

    /**
     * The face of the last reinit() between @p cell and @p neighbor in the
     * dofs of their flow elements: element_dofs, their component, and the
     * expansion of every interface dof (the identity where the side's
     * element is the cell itself, the parent's Q1 interpolation where it is
     * the parent).
     */
    void
    expand_to_elements(const typename DoFHandler<dim>::cell_iterator &cell,
                       const typename DoFHandler<dim>::cell_iterator &neighbor);

    /** The matrices of the face of the last expand_to_elements(), in
     * element_dofs. */
    void
    compute(const Weights &weights);

    /**
     * Whether the face @p f of @p cell (on its element's boundary) lies
     * between two flow elements of the same size, as every face in the band
     * does: with parents, two parents or a parent and a cell of the
     * parents' level; else two cells of one level.
     */
    bool
    between_equal_elements(const typename DoFHandler<dim>::cell_iterator &cell,
                           const unsigned int f) const;

    /**
     * The whole face between the elements of @p lower and @p upper (cells
     * of each, adjacent across the face, @p upper beyond @p lower in
     * direction @p direction), elements of the same size: element_dofs,
     * component, and the matrices in closed form. For Q1 on boxes the jump
     * of the normal derivative at the face is the second difference of the
     * three layers of vertices, (-1, 2, -1) / h_d, times the Q1 face
     * interpolant, so each component's matrix is that difference's outer
     * product times the face's Q1 mass matrix; no quadrature, and one face
     * of a parent instead of its children's quarters.
     */
    void
    compute_between_equal_elements(
      const typename DoFHandler<dim>::cell_iterator &lower,
      const typename DoFHandler<dim>::cell_iterator &upper,
      const unsigned int                             direction,
      const Weights                                 &weights);

    /**
     * A face's matrices as compute() made them: row by row the entries
     * that couple a component with itself (the others are zero), and of the
     * Schur matrix those of the pressure.
     */
    struct KeptFace
    {
      std::vector<types::global_dof_index> dofs;
      std::vector<unsigned int>            component;
      std::vector<double>                  matrix;
      std::vector<double>                  schur;
    };

    void
    keep_face(const std::vector<types::global_dof_index> &dofs);

    void
    recall_face(const KeptFace &face);

    const FlowStepParameters parameters;
    /** The step of the mass term (StokesCellSystem::mass_tau). */
    const double              mass_tau;
    const double              mu;
    const FiniteElement<dim> &flow_fe;
    const FlowElements<dim>  &elements;
    FEInterfaceValues<dim>    interface_values;
    FullMatrix<double>        matrix;
    FullMatrix<double>        schur;
    /** Of the face being computed: the dofs of both flow elements and the
     * component of each. */
    std::vector<types::global_dof_index> element_dofs;
    std::vector<unsigned int>            component;
    /** By interface dof: (index in element_dofs, weight). */
    std::vector<std::vector<std::pair<unsigned int, double>>> expansion;
    std::vector<double>                                       jump;
    std::vector<KeptFace>                                     kept_faces;
    bool wall_faces_kept = false;
  };
} // namespace vefs

#endif
