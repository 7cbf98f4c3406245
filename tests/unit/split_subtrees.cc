// mend_split_subtrees() (transport/split_subtrees.h) on the unit square:
// level 1, then three rounds of refinement toward the circle |x| = 0.7, so
// that the level-1 cells near it hold subtrees of depth 2 and 3, first
// with p4est's own partition (which cuts such subtrees on 2 and 3 ranks:
// unit/subtree_partition), as a loaded checkpoint has it. Then the
// partition's weights are connected and mend_split_subtrees() called, with
// the fields (level set and velocity linear in x, stress constant) and
// the level set gradient (a copy of the fields) on the mesh: afterwards no
// subtree of a level-1 cell is split, and both vectors still hold the same
// functions at every vertex of the owned cells, exactly (round-off of the
// transfer: below 1e-12). 1 and 2 ranks print the same; on 2 and 3
// ranks the subtrees are split before (VEFS_UNIT_VERBOSE=1 shows it).

#include "unit_test.h"

#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/grid/grid_generator.h>

#include <vefs/transport/split_subtrees.h>
#include <vefs/transport/subtree_partition.h>

#include <iostream>

using namespace dealii;

namespace
{
  /** Component c of the fields set up below, at @p p. */
  double
  exact(const Point<2> &p, const unsigned int c)
  {
    switch (c)
      {
        case 0:
          return 1 + 2 * p[0] - p[1];
        case 1:
          return -0.5 * p[0] + 3 * p[1];
        case 2:
          return p[0] + p[1] - 0.9;
        default:
          return 0.1 * c;
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  return unit_test::run(argc, argv, [](std::ostream &out) {
    const MPI_Comm                          comm = MPI_COMM_WORLD;
    parallel::distributed::Triangulation<2> triangulation(
      comm,
      Triangulation<2>::limit_level_difference_at_vertices,
      parallel::distributed::Triangulation<
        2>::mesh_reconstruction_after_repartitioning);
    GridGenerator::hyper_cube(triangulation, 0, 1);
    triangulation.refine_global(1);
    unit_test::refine_toward_circle(triangulation);

    vefs::TransportedFields<2> fields(triangulation, true, false, {});
    fields.setup_dofs();
    const ScalarFunctionFromFunctionObject<2> level_set(
      [](const Point<2> &p) { return exact(p, 2); });
    // The velocity (two components) and the constant stress.
    class Velocity : public Function<2>
    {
    public:
      Velocity()
        : Function<2>(2)
      {
      }
      double
      value(const Point<2> &p, const unsigned int c) const override
      {
        return exact(p, c);
      }
    } velocity;
    Vector<double> stress_values(3);
    for (unsigned int i = 0; i < 3; ++i)
      stress_values[i] = exact(Point<2>(), 3 + i);
    const Functions::ConstantFunction<2> stress(stress_values);
    fields.interpolate(level_set, velocity, &stress);
    vefs::LevelSetGradient<2> gradient;
    gradient.reinit(fields);
    gradient.mutable_vector() = fields.vector();
    gradient.finalize(fields);
    vefs::LevelSetHistory<2> history(0);

    vefs::SubtreePartition<2>(
      1,
      [](const typename Triangulation<2>::cell_iterator &,
         const typename Triangulation<2>::CellStatus) { return 1u; })
      .connect_to(triangulation);
    if (std::getenv("VEFS_UNIT_VERBOSE"))
      std::cerr << "before: subtrees_split(): "
                << vefs::subtrees_split(triangulation, 1) << '\n';
    vefs::mend_split_subtrees(triangulation, 1, fields, gradient, history);

    out << "after: subtrees_split(): "
        << (vefs::subtrees_split(triangulation, 1) ? "yes" : "no") << '\n';
    double field_error = 0, gradient_error = 0;
    for (const auto &cell : fields.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          for (unsigned int c = 0; c < fields.n_components; ++c)
            {
              const double expected = exact(cell->vertex(v), c);
              field_error =
                std::max(field_error,
                         std::abs(fields.value_at(cell, v, c) - expected));
              gradient_error =
                std::max(gradient_error,
                         std::abs(
                           gradient.vector()(cell->vertex_dof_index(v, c)) -
                           expected));
            }
    unit_test::check_below(out,
                           "after: fields, largest error at a vertex",
                           Utilities::MPI::max(field_error, comm),
                           1e-12);
    unit_test::check_below(out,
                           "after: level set gradient, largest error",
                           Utilities::MPI::max(gradient_error, comm),
                           1e-12);
    out << "every rank owns cells: "
        << (Utilities::MPI::min(triangulation.n_locally_owned_active_cells(),
                                comm) > 0
              ? "yes"
              : "NO")
        << '\n';
  });
}
