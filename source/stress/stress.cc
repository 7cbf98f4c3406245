#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <vefs/stress/stress.h>
#include <vefs/transport/free_surface.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace vefs
{
  namespace
  {
    /**
     * Smallest eigenvalue of a symmetric tensor, real even when the tensor
     * is close to a multiple of the identity (the closed form of
     * eigenvalues() then takes the root of a slightly negative number).
     */
    double
    smallest_eigenvalue(const SymmetricTensor<2, 2> &c)
    {
      const double mean = 0.5 * (c[0][0] + c[1][1]);
      const double half = 0.5 * (c[0][0] - c[1][1]);
      return mean - std::sqrt(half * half + c[0][1] * c[0][1]);
    }

    double
    smallest_eigenvalue(const SymmetricTensor<2, 3> &c)
    {
      // A blown-up stress (infinite, or so large that the rotations do not
      // converge) has no smallest eigenvalue: NaN, which the health check
      // reports, instead of deal.II's exception out of the postprocessing.
      if (!std::isfinite(c.norm()))
        return std::numeric_limits<double>::quiet_NaN();
      try
        {
          // Jacobi rotations: robust for clustered eigenvalues; sorted in
          // descending order.
          return eigenvectors(c, SymmetricTensorEigenvectorMethod::jacobi)[2]
            .first;
        }
      catch (const ExceptionBase &)
        {
          return std::numeric_limits<double>::quiet_NaN();
        }
    }

    /**
     * A lower bound of the eigenvalues of @p c (Gershgorin's circles): the
     * smallest diagonal entry less the other entries of its row, in
     * magnitude. NaN if @p c is not finite.
     */
    template <int dim>
    double
    gershgorin_lower_bound(const SymmetricTensor<2, dim> &c)
    {
      if (!std::isfinite(c.norm()))
        return std::numeric_limits<double>::quiet_NaN();
      double bound = std::numeric_limits<double>::max();
      for (unsigned int i = 0; i < dim; ++i)
        {
          double row = c[i][i];
          for (unsigned int j = 0; j < dim; ++j)
            if (j != i)
              row -= std::abs(c[i][j]);
          bound = std::min(bound, row);
        }
      return bound;
    }

    /**
     * How much more stretch (tr B - d) a node outside the liquid may carry
     * than the liquid nodes of its cells. Any finite factor ends the
     * runaway; the outside nodes of the thin sheets of the soft ball
     * (prm/bouncing_ball_2d_wide.prm) carry up to a few times the stretch
     * of the liquid nodes: a factor of 1 spreads that ball to 1.38 m
     * instead of 1.01 m, 3 to 1.20 m, 10 leaves it as without the bound
     * (doc/bouncing_ball.md).
     */
    constexpr double stretch_bound_factor = 10;

    /**
     * The nodes outside the liquid (psi > 0) of cells with liquid may not
     * be stretched far more than the liquid: where tr B - d at such a node
     * exceeds stretch_bound_factor times the largest tr B - d at the liquid
     * nodes (psi <= 0) of its liquid cells, B becomes I + s (B - I),
     * 0 <= s < 1, with that trace (a convex combination of I and B:
     * positive definite). Nothing in the flow step
     * resists the stretching of these nodes: their velocity is set by the
     * ghost penalty and a sliver of liquid, and their stress enters the
     * liquid only through the Q1 interpolation. Unbounded, it grows by the
     * strain bound in every step while the step shrinks (the beam held by
     * a no-slip wall, doc/oscillating_beam.md). @p updated is nonzero at the
     * nodes the update has just set.
     */
    template <int dim>
    void
    bound_stress_outside_liquid(
      TransportedFields<dim>                            &fields,
      const LiquidDomain<dim>                           &domain,
      const Rheology<dim>                               &rheology,
      const typename TransportedFields<dim>::VectorType &updated)
    {
      constexpr unsigned int n_stress =
        TransportedFields<dim>::n_stress_components;
      const auto conformation_trace =
        [&](const SymmetricTensor<2, dim> &sigma) {
          return trace(rheology.conformation(sigma));
        };

      typename TransportedFields<dim>::VectorType largest;
      fields.initialize_vector(largest);
      for (const auto &cell : fields.dof_handler.active_cell_iterators())
        if (cell->is_locally_owned() && domain.has_liquid(cell))
          {
            double in_liquid = 0;
            for (const unsigned int v : cell->vertex_indices())
              if (fields.level_set_at(cell, v) <= 0)
                in_liquid =
                  std::max(in_liquid,
                           conformation_trace(fields.stress_at(cell, v)));
            for (const unsigned int v : cell->vertex_indices())
              {
                double &entry = fields.entry_at(largest, cell, v, 0);
                entry         = std::max(entry, in_liquid);
              }
          }
      largest.compress(VectorOperation::max);

      for (const auto &node : fields.nodes())
        if (updated(node.dofs[0]) > 0 && fields.level_set(node) > 0 &&
            largest(node.dofs[0]) > 0)
          {
            SymmetricTensor<2, dim> sigma = fields.stress(node);
            const double            now   = conformation_trace(sigma);
            const double            bound =
              dim + stretch_bound_factor *
                      std::max<double>(largest(node.dofs[0]) - dim, 0.);
            if (now > bound)
              {
                const double s = (bound - dim) / (now - dim);
                for (unsigned int i = 0; i < n_stress; ++i)
                  sigma.access_raw_entry(i) *= s;
                fields.set_stress(node, sigma);
              }
          }
      fields.finalize();
    }

    /**
     * Calls @p visit for each quadrature point q of the liquid part of each
     * locally owned liquid cell with the cell's values there, sigma*_q (the
     * Q1 interpolant of the nodal stress) and the update of sigma*_q by the
     * traceless Q1 gradient L_q of @p velocity: the stress update at the
     * points where the flow step does work against the stress.
     */
    template <int dim, typename Visitor>
    void
    for_each_liquid_point(
      const TransportedFields<dim>                      &fields,
      const typename TransportedFields<dim>::VectorType &velocity,
      const LiquidDomain<dim>                           &domain,
      const Rheology<dim>                               &rheology,
      const double                                       tau,
      const Visitor                                     &visit)
    {
      LiquidValues<dim> liquid_values(domain);
      std::array<SymmetricTensor<2, dim>, GeometryInfo<dim>::vertices_per_cell>
        vertex_sigma;
      std::array<Tensor<1, dim>, GeometryInfo<dim>::vertices_per_cell> vertex_u;
      for (const auto &cell : fields.dof_handler.active_cell_iterators())
        if (cell->is_locally_owned() && domain.has_liquid(cell))
          {
            for (const unsigned int v : cell->vertex_indices())
              {
                vertex_sigma[v] = fields.stress_at(cell, v);
                for (unsigned int d = 0; d < dim; ++d)
                  vertex_u[v][d] = fields.entry_at(velocity, cell, v, d);
              }
            const BoxCellValues<dim> &values = liquid_values.reinit(cell);
            for (unsigned int q = 0; q < values.size(); ++q)
              {
                Tensor<2, dim> L;
                for (const unsigned int v : cell->vertex_indices())
                  for (unsigned int d = 0; d < dim; ++d)
                    L[d] += vertex_u[v][d] * values.gradient[q][v];
                const SymmetricTensor<2, dim> advected =
                  values.value(vertex_sigma, q);
                visit(cell,
                      values,
                      q,
                      advected,
                      rheology.updated_stress(advected, traceless(L), tau));
              }
          }
    }

    /**
     * The increment sigma(sigma*_q, L_q) - sigma*_q of the update at the
     * quadrature points of each liquid cell's liquid part (sigma* the Q1
     * interpolant of the nodes, L_q the traceless Q1 velocity gradient),
     * summed into @p increment as the integrals against the shape
     * functions, whose own integrals over the liquid go into the node's
     * first component: the lumped L2 projection of the increment. These
     * are the points where the flow step did work against the stress, so
     * that the nodes gain nearly the work the flow step saw
     * (doc/bouncing_ball.md, "Energy budget"). Lumped, not the consistent
     * projection: one Jacobi sweep toward it took the 2D stiff ball's first
     * contact loss at 3.12 mm from 4.2 to 2.3 %, but at 1.56 mm made the
     * second contact gain 10.5 J/m, and liquid slivers in cut cells make
     * the converged projection cost hundreds of CG iterations.
     */
    template <int dim>
    void
    lump_increment(const TransportedFields<dim>                      &fields,
                   const typename TransportedFields<dim>::VectorType &velocity,
                   const LiquidDomain<dim>                           &domain,
                   const Rheology<dim>                               &rheology,
                   const double                                       tau,
                   typename TransportedFields<dim>::VectorType       &increment)
    {
      constexpr unsigned int first =
        TransportedFields<dim>::first_stress_component;
      constexpr unsigned int n_stress =
        TransportedFields<dim>::n_stress_components;
      fields.initialize_vector(increment);
      for_each_liquid_point(
        fields,
        velocity,
        domain,
        rheology,
        tau,
        [&](const auto                    &cell,
            const BoxCellValues<dim>      &values,
            const unsigned int             q,
            const SymmetricTensor<2, dim> &advected,
            const SymmetricTensor<2, dim> &updated) {
          const SymmetricTensor<2, dim> change = updated - advected;
          for (const unsigned int v : cell->vertex_indices())
            {
              const double weight = values.shape[q][v] * values.JxW[q];
              fields.entry_at(increment, cell, v, 0) += weight;
              for (unsigned int i = 0; i < n_stress; ++i)
                fields.entry_at(increment, cell, v, first + i) +=
                  weight * change.access_raw_entry(i);
            }
        });
      increment.compress(VectorOperation::add);
    }

  } // namespace

  template <int dim>
  StressUpdateReport
  for_each_liquid_vertex(
    const TransportedFields<dim>                      &fields,
    const typename TransportedFields<dim>::VectorType &velocity,
    const LiquidDomain<dim>                           &domain,
    const Rheology<dim>                               &rheology,
    const double                                       tau,
    const std::function<
      void(const typename DoFHandler<dim>::active_cell_iterator &cell,
           const unsigned int                                    v,
           const Tensor<2, dim> &grad_u)> &carry)
  {
    // Quadrature points at the vertices, in the vertex order of the cell.
    // In closed form: an FEValues of the fields' element costs the square
    // of their number of components to build (the dumbbells' fields).
    const QTrapezoid<dim>       at_vertices;
    BoxCellValues<dim>          vertex_values;
    std::vector<Tensor<2, dim>> grad_u(GeometryInfo<dim>::vertices_per_cell);
    LiquidValues<dim>           liquid_values(domain);
    std::array<Tensor<1, dim>, GeometryInfo<dim>::vertices_per_cell> vertex_u;
    StressUpdateReport                                               report;
    for (const auto &cell : fields.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && domain.has_liquid(cell))
        {
          for (const unsigned int v : cell->vertex_indices())
            for (unsigned int d = 0; d < dim; ++d)
              vertex_u[v][d] = fields.entry_at(velocity, cell, v, d);
          if (domain.location(cell) == LiquidDomain<dim>::Location::cut)
            {
              // A cut cell carries the stress at all its vertices by the
              // mean velocity gradient of its liquid part: the gradient the
              // flow step's stress term sees there. The Q1 gradient at a
              // vertex outside the liquid depends on velocities that only
              // the ghost penalty and a sliver of liquid set; the stress
              // it stretches there enters the liquid through the Q1
              // interpolation, without the flow step resisting that
              // stretching, and grows by the strain bound in every step
              // (the beam held by a no-slip wall, doc/oscillating_beam.md).
              const BoxCellValues<dim> &values = liquid_values.reinit(cell);
              Tensor<2, dim>            mean;
              double                    volume = 0;
              for (unsigned int q = 0; q < values.size(); ++q)
                {
                  for (const unsigned int v : cell->vertex_indices())
                    for (unsigned int d = 0; d < dim; ++d)
                      mean[d] +=
                        vertex_u[v][d] * values.JxW[q] * values.gradient[q][v];
                  volume += values.JxW[q];
                }
              if (volume > 0)
                mean /= volume;
              std::fill(grad_u.begin(), grad_u.end(), mean);
            }
          else
            {
              vertex_values.reinit(cell, at_vertices);
              for (const unsigned int v : cell->vertex_indices())
                {
                  grad_u[v] = 0;
                  for (const unsigned int w : cell->vertex_indices())
                    for (unsigned int d = 0; d < dim; ++d)
                      grad_u[v][d] +=
                        vertex_u[w][d] * vertex_values.gradient[v][w];
                }
            }
          for (const unsigned int v : cell->vertex_indices())
            {
              const Tensor<2, dim> L = traceless(grad_u[v]);
              report.max_velocity_gradient =
                std::max(report.max_velocity_gradient, grad_u[v].norm());
              if (rheology.is_strain_limited(L, tau))
                ++report.strain_limited_points;
              carry(cell, v, L);
            }
        }

    const MPI_Comm comm =
      fields.dof_handler.get_triangulation().get_communicator();
    report.max_velocity_gradient =
      Utilities::MPI::max(report.max_velocity_gradient, comm);
    report.strain_limited_points =
      Utilities::MPI::sum(report.strain_limited_points, comm);
    return report;
  }

  template <int dim>
  StressUpdateReport
  update_stress(TransportedFields<dim>                            &fields,
                const typename TransportedFields<dim>::VectorType &velocity,
                const LiquidDomain<dim>                           &domain,
                const Rheology<dim>                               &rheology,
                const double                                       tau,
                const bool        outside_extended,
                const NodalStress nodal_stress)
  {
    using VectorType = typename TransportedFields<dim>::VectorType;
    constexpr unsigned int first =
      TransportedFields<dim>::first_stress_component;
    constexpr unsigned int n_stress =
      TransportedFields<dim>::n_stress_components;

    Assert(nodal_stress != NodalStress::automatic,
           ExcMessage("StressParameters::resolve_nodal_stress() first."));
    // Read before the nodes change.
    const bool lumped = nodal_stress == NodalStress::lumped_increment;
    VectorType increment;
    if (lumped)
      lump_increment(fields, velocity, domain, rheology, tau, increment);

    // Sum over the liquid cells around each node of volume * new stress;
    // the volume itself goes into the node's first component.
    VectorType sum;
    fields.initialize_vector(sum);
    const StressUpdateReport report = for_each_liquid_vertex<dim>(
      fields,
      velocity,
      domain,
      rheology,
      tau,
      [&](const auto &cell, const unsigned int v, const Tensor<2, dim> &L) {
        const SymmetricTensor<2, dim> updated =
          rheology.updated_stress(fields.stress_at(cell, v), L, tau);
        const double weight = cell->measure();
        fields.entry_at(sum, cell, v, 0) += weight;
        for (unsigned int i = 0; i < n_stress; ++i)
          fields.entry_at(sum, cell, v, first + i) +=
            weight * updated.access_raw_entry(i);
      });
    sum.compress(VectorOperation::add);

    for (const auto &node : fields.nodes())
      {
        const double weight = sum(node.dofs[0]);
        if (weight > 0)
          {
            SymmetricTensor<2, dim> sigma;
            for (unsigned int i = 0; i < n_stress; ++i)
              sigma.access_raw_entry(i) = sum(node.dofs[first + i]) / weight;
            if (lumped && increment(node.dofs[0]) > 0)
              {
                // The lumping mixes the increments of neighbouring points
                // and so may overshoot where the average does not.
                SymmetricTensor<2, dim> lumped_sigma = fields.stress(node);
                for (unsigned int i = 0; i < n_stress; ++i)
                  lumped_sigma.access_raw_entry(i) +=
                    increment(node.dofs[first + i]) / increment(node.dofs[0]);
                if (smallest_eigenvalue(rheology.conformation(lumped_sigma)) >=
                    0.5 * smallest_eigenvalue(rheology.conformation(sigma)))
                  sigma = lumped_sigma;
              }
            fields.set_stress(node, sigma);
          }
      }
    fields.finalize();
    if (!outside_extended)
      bound_stress_outside_liquid(fields, domain, rheology, sum);
    return report;
  }

  template <int dim>
  double
  elastic_energy_of_pointwise_update(
    const TransportedFields<dim>                      &fields,
    const typename TransportedFields<dim>::VectorType &velocity,
    const LiquidDomain<dim>                           &domain,
    const Rheology<dim>                               &rheology,
    const double                                       tau)
  {
    double energy = 0;
    for_each_liquid_point(fields,
                          velocity,
                          domain,
                          rheology,
                          tau,
                          [&](const auto &,
                              const BoxCellValues<dim> &values,
                              const unsigned int        q,
                              const SymmetricTensor<2, dim> &,
                              const SymmetricTensor<2, dim> &updated) {
                            energy += rheology.elastic_energy_density(updated) *
                                      values.JxW[q];
                          });
    return Utilities::MPI::sum(
      energy,
      fields.dof_handler.get_triangulation().get_communicator());
  }

  template <int dim>
  StressMeasure
  measure_stress(const TransportedFields<dim> &fields,
                 const LiquidDomain<dim>      &domain,
                 const Rheology<dim>          &rheology)
  {
    LiquidValues<dim> liquid_values(domain);
    std::array<SymmetricTensor<2, dim>, GeometryInfo<dim>::vertices_per_cell>
      vertex_sigma;

    StressMeasure measure;
    bool          undefined_eigenvalue = false;
    for (const auto &cell : fields.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && domain.has_liquid(cell))
        {
          for (const unsigned int v : cell->vertex_indices())
            vertex_sigma[v] = fields.stress_at(cell, v);
          const BoxCellValues<dim> &values = liquid_values.reinit(cell);
          for (unsigned int q = 0; q < values.size(); ++q)
            {
              const SymmetricTensor<2, dim> sigma =
                values.value(vertex_sigma, q);
              measure.elastic_energy +=
                rheology.elastic_energy_density(sigma) * values.JxW[q];
              const SymmetricTensor<2, dim> conformation =
                rheology.conformation(sigma);
              // Where even the bound is positive and above the smallest
              // eigenvalue so far, the eigenvalue changes no statistic.
              const double bound = gershgorin_lower_bound(conformation);
              if (bound > 0 && bound >= measure.min_conformation_eigenvalue)
                continue;
              const double lowest = smallest_eigenvalue(conformation);
              measure.min_conformation_eigenvalue =
                std::min(measure.min_conformation_eigenvalue, lowest);
              if (std::isnan(lowest))
                undefined_eigenvalue = true;
              if (!(lowest > 0))
                ++measure.non_positive_points;
            }
        }
    const MPI_Comm comm =
      fields.dof_handler.get_triangulation().get_communicator();
    measure.elastic_energy = Utilities::MPI::sum(measure.elastic_energy, comm);
    measure.min_conformation_eigenvalue =
      Utilities::MPI::min(measure.min_conformation_eigenvalue, comm);
    measure.non_positive_points =
      Utilities::MPI::sum(measure.non_positive_points, comm);
    // std::min() passes over NaN: carry it to the statistic by hand.
    if (Utilities::MPI::max(static_cast<unsigned int>(undefined_eigenvalue),
                            comm) == 1)
      measure.min_conformation_eigenvalue =
        std::numeric_limits<double>::quiet_NaN();
    return measure;
  }

  template StressUpdateReport
  update_stress<2>(TransportedFields<2> &,
                   const TransportedFields<2>::VectorType &,
                   const LiquidDomain<2> &,
                   const Rheology<2> &,
                   const double,
                   const bool,
                   const NodalStress);
  template StressUpdateReport
  update_stress<3>(TransportedFields<3> &,
                   const TransportedFields<3>::VectorType &,
                   const LiquidDomain<3> &,
                   const Rheology<3> &,
                   const double,
                   const bool,
                   const NodalStress);
  template StressUpdateReport
  for_each_liquid_vertex<2>(
    const TransportedFields<2> &,
    const TransportedFields<2>::VectorType &,
    const LiquidDomain<2> &,
    const Rheology<2> &,
    const double,
    const std::function<void(const DoFHandler<2>::active_cell_iterator &,
                             const unsigned int,
                             const Tensor<2, 2> &)> &);
  template StressUpdateReport
  for_each_liquid_vertex<3>(
    const TransportedFields<3> &,
    const TransportedFields<3>::VectorType &,
    const LiquidDomain<3> &,
    const Rheology<3> &,
    const double,
    const std::function<void(const DoFHandler<3>::active_cell_iterator &,
                             const unsigned int,
                             const Tensor<2, 3> &)> &);
  template StressMeasure
  measure_stress<2>(const TransportedFields<2> &,
                    const LiquidDomain<2> &,
                    const Rheology<2> &);
  template StressMeasure
  measure_stress<3>(const TransportedFields<3> &,
                    const LiquidDomain<3> &,
                    const Rheology<3> &);
  template double
  elastic_energy_of_pointwise_update<2>(
    const TransportedFields<2> &,
    const TransportedFields<2>::VectorType &,
    const LiquidDomain<2> &,
    const Rheology<2> &,
    const double);
  template double
  elastic_energy_of_pointwise_update<3>(
    const TransportedFields<3> &,
    const TransportedFields<3>::VectorType &,
    const LiquidDomain<3> &,
    const Rheology<3> &,
    const double);
} // namespace vefs
