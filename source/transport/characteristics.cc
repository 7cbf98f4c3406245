#include <deal.II/base/mpi.h>

#include <boost/container/small_vector.hpp>
#include <vefs/transport/characteristics.h>
#include <vefs/transport/field_hermite.h>
#include <vefs/transport/gradient_consistency.h>
#include <vefs/transport/nodal_gradients.h>

namespace vefs
{
  namespace
  {
    /**
     * Values of all components of the fields at one point, followed by
     * extras: the velocity gradient du_i/dx_j at extra(dim i + j), or the
     * level set gradient at extra(d). Sized at run time (the fields'
     * components are), on the stack for the fields without dumbbells.
     */
    template <int dim>
    class FieldValues
    {
    public:
      static constexpr unsigned int n_extras = dim * dim;

      FieldValues() = default;

      explicit FieldValues(const unsigned int n_components)
        : values(n_components + n_extras, 0.)
        , first_extra(n_components)
      {
      }

      double &
      operator[](const unsigned int c)
      {
        return values[c];
      }

      double
      operator[](const unsigned int c) const
      {
        return values[c];
      }

      double &
      extra(const unsigned int k)
      {
        return values[first_extra + k];
      }

      double
      extra(const unsigned int k) const
      {
        return values[first_extra + k];
      }

      /** Components and extras. */
      unsigned int
      size() const
      {
        return values.size();
      }

    private:
      boost::container::
        small_vector<double, TransportedFields<dim>::max_components + n_extras>
                   values;
      unsigned int first_extra = 0;
    };

    /** How values_in_cell interpolates, and which extras it adds. */
    template <int dim>
    struct Interpolation
    {
      /**
       * The level set by this gradient-augmented Hermite interpolation, if
       * not null, and its gradient as extras.
       */
      const FieldHermite<dim> *hermite = nullptr;
      /**
       * If not null, the level set's Hermite cubic is also limited in the
       * cells at these contact walls.
       */
      const BoxMeshLocator<dim> *limited_at_contact_walls = nullptr;
      /**
       * Extras: the velocity gradient, Q1 from these nodal gradients (see
       * recover_nodal_gradients()), if not null.
       */
      const std::array<typename TransportedFields<dim>::VectorType, dim>
        *velocity_gradient = nullptr;
      /**
       * The detail of the cells the last mesh change coarsened, if not null:
       * Q1 in the former child there.
       */
      const CoarsenedDetail<dim> *coarsened_detail = nullptr;
      /**
       * The velocity by this Hermite interpolation, if not null, and with it
       * the acceleration of the second-order scheme: the velocity slots hold
       * u + tau/2 a while the feet are traced, and u(X) = (u + tau/2 a)(X) -
       * tau/2 a(X) only if both are interpolated alike. With a Q1 a(X) the
       * difference enters a = (u - u*) / (w tau) - ((1 - w) / w) a*, whose
       * factor -(1 - w) / w = -0.96 it pushes beyond -1 for an alternating
       * mode: the stiff beam at rest grew such a mode from t = 2.2 s
       * (doc/bouncing_ball.md, "What `automatic` gives a stiff solid").
       */
      const FieldHermite<dim>  *velocity_hermite = nullptr;
      bool                      velocity_limited = false;
      std::vector<unsigned int> velocity_components;
      /**
       * The stress by this limited Hermite interpolation, if not null, where
       * it keeps c = I + sigma / G (G = shear_modulus) positive definite.
       */
      const FieldHermite<dim> *stress_hermite = nullptr;
      double                   shear_modulus  = 1;
    };

    /**
     * The fields at the unit-cell point @p xi of @p cell (locally owned or
     * ghost): Q1 unless @p how says otherwise.
     */
    template <int dim>
    FieldValues<dim>
    values_in_cell(
      const typename Triangulation<dim>::active_cell_iterator &cell,
      const Point<dim>                                        &xi,
      const TransportedFields<dim>                            &fields,
      const Interpolation<dim>                                &how)
    {
      constexpr unsigned int level_set =
        TransportedFields<dim>::level_set_component;
      FieldValues<dim> values(fields.n_components);
      const auto       dof_cell = fields.cell_of(cell);
      const auto       entries  = fields.vertex_entries(dof_cell);
      if (const double *lattice = how.coarsened_detail
                                    ? how.coarsened_detail->lattice(cell)
                                    : nullptr)
        // Coarsened before this advection: Q1 in the former child.
        how.coarsened_detail->add_values(lattice, xi, &values[0]);
      else
        for (const unsigned int v : cell->vertex_indices())
          {
            const double weight = BoxMeshLocator<dim>::vertex_weight(xi, v);
            for (unsigned int c = 0; c < fields.n_components; ++c)
              values[c] += weight * fields.local_value(entries[v] + c);
          }
      if (how.velocity_gradient)
        for (const unsigned int v : cell->vertex_indices())
          {
            const double weight = BoxMeshLocator<dim>::vertex_weight(xi, v);
            for (unsigned int i = 0; i < dim; ++i)
              for (unsigned int j = 0; j < dim; ++j)
                values.extra(dim * i + j) +=
                  weight *
                  (*how.velocity_gradient)[j].local_element(entries[v] + i);
          }
      if (how.velocity_hermite)
        for (const unsigned int c : how.velocity_components)
          values[c] =
            how.velocity_hermite->component_value(fields,
                                                  dof_cell,
                                                  entries,
                                                  xi,
                                                  c,
                                                  how.velocity_limited);
      if (how.stress_hermite)
        {
          constexpr unsigned int first =
            TransportedFields<dim>::first_stress_component;
          SymmetricTensor<2, dim> linear, cubic;
          for (unsigned int i = 0;
               i < TransportedFields<dim>::n_stress_components;
               ++i)
            {
              linear.access_raw_entry(i) = values[first + i];
              cubic.access_raw_entry(i) =
                how.stress_hermite->component_value(fields,
                                                    dof_cell,
                                                    entries,
                                                    xi,
                                                    first + i,
                                                    true);
            }
          const auto smallest = [&](const SymmetricTensor<2, dim> &sigma) {
            return eigenvalues(unit_symmetric_tensor<dim>() +
                               sigma / how.shear_modulus)[dim - 1];
          };
          // The cubic stress only where c keeps at least half the smallest
          // eigenvalue of the linear (convex) one.
          if (smallest(cubic) >= 0.5 * smallest(linear))
            for (unsigned int i = 0;
                 i < TransportedFields<dim>::n_stress_components;
                 ++i)
              values[first + i] = cubic.access_raw_entry(i);
        }
      if (how.hermite)
        {
          Tensor<1, dim> gradient;
          values[level_set] = how.hermite->value(
            fields,
            dof_cell,
            entries,
            xi,
            how.limited_at_contact_walls &&
              how.limited_at_contact_walls->touches_contact_wall(cell),
            &gradient);
          for (unsigned int d = 0; d < dim; ++d)
            values.extra(d) = gradient[d];
        }
      return values;
    }

    /**
     * The fields at @p points, which lie in cells artificial on this rank:
     * the locator names the rank that owns each point (from p4est's
     * partition), and that rank locates and evaluates it. Collective.
     * (deal.II 9.4's RemotePointEvaluation searched all active cells for
     * every point: 77 % of a step of the 3D ball at 2.5 mm on two ranks.)
     */
    template <int dim>
    std::vector<FieldValues<dim>>
    evaluate_remotely(const std::vector<Point<dim>> &points,
                      const TransportedFields<dim>  &fields,
                      const BoxMeshLocator<dim>     &locator,
                      const Interpolation<dim>      &how)
    {
      const MPI_Comm comm =
        fields.dof_handler.get_triangulation().get_communicator();
      std::vector<types::subdomain_id> owners(points.size());
      for (unsigned int i = 0; i < points.size(); ++i)
        owners[i] = locator.owner_rank(points[i]);

      // Coordinates to the owners, flat.
      std::map<unsigned int, std::vector<double>>       asked;
      std::map<unsigned int, std::vector<unsigned int>> asked_points;
      for (unsigned int i = 0; i < points.size(); ++i)
        {
          asked_points[owners[i]].push_back(i);
          for (unsigned int d = 0; d < dim; ++d)
            asked[owners[i]].push_back(points[i][d]);
        }

      const unsigned int n_values =
        FieldValues<dim>(fields.n_components).size();
      std::map<unsigned int, std::vector<double>> answers;
      for (const auto &[rank, coordinates] :
           Utilities::MPI::some_to_some(comm, asked))
        {
          auto &answer = answers[rank];
          answer.reserve(coordinates.size() / dim * n_values);
          for (unsigned int k = 0; k < coordinates.size(); k += dim)
            {
              Point<dim> p;
              for (unsigned int d = 0; d < dim; ++d)
                p[d] = coordinates[k + d];
              const auto [cell, xi] = locator.locate_with_unit_point(p);
              AssertThrow(!cell->is_artificial(),
                          ExcMessage("A point p4est places on this rank lies "
                                     "in a cell it does not know."));
              const auto values = values_in_cell(cell, xi, fields, how);
              for (unsigned int c = 0; c < n_values; ++c)
                answer.push_back(values[c]);
            }
        }

      std::vector<FieldValues<dim>> result(points.size(),
                                           FieldValues<dim>(
                                             fields.n_components));
      for (const auto &[rank, values] :
           Utilities::MPI::some_to_some(comm, answers))
        {
          const auto &indices = asked_points.at(rank);
          AssertThrow(values.size() == indices.size() * n_values,
                      ExcInternalError());
          for (unsigned int k = 0; k < indices.size(); ++k)
            for (unsigned int c = 0; c < n_values; ++c)
              result[indices[k]][c] = values[k * n_values + c];
        }
      return result;
    }

    /**
     * The fields at arbitrary points: in the local part of the mesh (owned
     * and ghost cells) in the cell the locator finds, elsewhere on the ranks
     * that own them (evaluate_remotely()).
     */
    template <int dim>
    std::vector<FieldValues<dim>>
    evaluate_at(const std::vector<Point<dim>> &points,
                const TransportedFields<dim>  &fields,
                const BoxMeshLocator<dim>     &locator,
                const Interpolation<dim>      &how)
    {
      std::vector<FieldValues<dim>> values(points.size());
      std::vector<unsigned int>     remote;
      for (unsigned int i = 0; i < points.size(); ++i)
        {
          const auto [cell, xi] = locator.locate_with_unit_point(points[i]);
          if (cell->is_artificial())
            {
              remote.push_back(i);
              continue;
            }
          values[i] = values_in_cell(cell, xi, fields, how);
        }

      const auto &triangulation = fields.dof_handler.get_triangulation();
      if (!Utilities::MPI::logical_or(!remote.empty(),
                                      triangulation.get_communicator()))
        return values;

      std::vector<Point<dim>> remote_points;
      for (const unsigned int i : remote)
        remote_points.push_back(points[i]);
      const auto remote_values =
        evaluate_remotely(remote_points, fields, locator, how);
      for (unsigned int k = 0; k < remote.size(); ++k)
        values[remote[k]] = remote_values[k];
      return values;
    }

    /**
     * Four-stage (classical Runge-Kutta) trace of @p starts back through
     * the frozen velocity field of @p fields over @p tau, given the
     * velocity @p k and its gradient @p dk at the starts (both overwritten
     * by those of the later stages): with the cubic
     * level set the error of the midpoint trace dominated at CFL 5 (vortex,
     * h = 1/128: L1 3.4e-3 -> 2.4e-3 with exact fourth-order feet). J =
     * dX/dx follows the stages, with the velocity gradient G recovered at
     * the nodes (the Q1 one is first order only): dk_s/dx = G(x_s) dx_s/dx.
     */
    template <int dim>
    void
    four_stage_trace(
      const TransportedFields<dim> &fields,
      const std::array<typename TransportedFields<dim>::VectorType, dim>
                                    &velocity_gradient,
      const double                   tau,
      const BoxMeshLocator<dim>     &locator,
      const std::vector<Point<dim>> &starts,
      std::vector<Tensor<1, dim>>   &k,
      std::vector<Tensor<2, dim>>   &dk,
      std::vector<Point<dim>>       &feet,
      std::vector<Tensor<2, dim>>   &jacobians,
      const CoarsenedDetail<dim>    *coarsened_detail)
    {
      Interpolation<dim> at_stage;
      at_stage.velocity_gradient    = &velocity_gradient;
      at_stage.coarsened_detail     = coarsened_detail;
      const Tensor<2, dim> identity = unit_symmetric_tensor<dim>();

      feet.resize(starts.size());
      jacobians.resize(starts.size());
      for (unsigned int i = 0; i < starts.size(); ++i)
        {
          feet[i]      = starts[i] - tau / 6 * k[i];
          jacobians[i] = identity - tau / 6 * dk[i];
        }
      std::vector<Point<dim>> points(starts.size());
      const double            fractions[3] = {0.5, 0.5, 1};
      const double            weights[3]   = {2, 2, 1};
      for (unsigned int stage = 0; stage < 3; ++stage)
        {
          for (unsigned int i = 0; i < starts.size(); ++i)
            points[i] = locator.fold_into_cavity(starts[i] -
                                                 fractions[stage] * tau * k[i]);
          const auto at_stage_points =
            evaluate_at(points, fields, locator, at_stage);
          for (unsigned int i = 0; i < starts.size(); ++i)
            {
              Tensor<2, dim> G;
              for (unsigned int a = 0; a < dim; ++a)
                {
                  k[i][a] = at_stage_points[i][a];
                  for (unsigned int b = 0; b < dim; ++b)
                    G[a][b] = at_stage_points[i].extra(dim * a + b);
                }
              dk[i] = G * (identity - fractions[stage] * tau * dk[i]);
              feet[i] -= weights[stage] * tau / 6 * k[i];
              jacobians[i] -= weights[stage] * tau / 6 * dk[i];
            }
        }
    }

    /**
     * How the level set is interpolated at the feet as @p interpolation
     * says: the gradient-augmented one recovers its Hermite data into
     * @p hermite, which must outlive the result.
     */
    template <int dim>
    Interpolation<dim>
    level_set_interpolation(const TransportedFields<dim> &fields,
                            const LevelSetGradient<dim>  &level_set_gradient,
                            const LevelSetInterpolation   interpolation,
                            FieldHermite<dim>            &hermite)
    {
      Interpolation<dim> how;
      if (interpolation == LevelSetInterpolation::gradient_augmented)
        {
          hermite.recover(fields, &level_set_gradient);
          how.hermite = &hermite;
        }
      return how;
    }

    /**
     * The feet of the characteristics of all owned nodes by the two-stage
     * (midpoint) trace, not yet moved back into the cavity.
     */
    template <int dim>
    std::vector<Point<dim>>
    midpoint_feet(const TransportedFields<dim> &fields,
                  const double                  tau,
                  const BoxMeshLocator<dim>    &locator,
                  const CoarsenedDetail<dim>   *coarsened_detail)
    {
      const auto             &nodes = fields.nodes();
      std::vector<Point<dim>> points(nodes.size());
      for (unsigned int i = 0; i < nodes.size(); ++i)
        points[i] = locator.fold_into_cavity(
          nodes[i].point - 0.5 * tau * fields.velocity(nodes[i]));
      Interpolation<dim> at_midpoint;
      at_midpoint.coarsened_detail = coarsened_detail;
      const auto at_midpoints =
        evaluate_at(points, fields, locator, at_midpoint);
      for (unsigned int i = 0; i < nodes.size(); ++i)
        {
          Tensor<1, dim> u;
          for (unsigned int d = 0; d < dim; ++d)
            u[d] = at_midpoints[i][d];
          points[i] = nodes[i].point - tau * u;
        }
      return points;
    }
  } // namespace

  template <int dim>
  void
  advect_along_characteristics(TransportedFields<dim>     &fields,
                               LevelSetGradient<dim>      &level_set_gradient,
                               const double                tau,
                               const BoxMeshLocator<dim>  &locator,
                               const FootInterpolation    &interpolation,
                               const CoarsenedDetail<dim> *coarsened_detail)
  {
    const auto &nodes = fields.nodes();

    const bool gradient_augmented =
      interpolation.level_set == LevelSetInterpolation::gradient_augmented;

    std::vector<Point<dim>> points(nodes.size());
    // The feet, and with the gradient augmented level set J = dX/dx.
    std::vector<Point<dim>>     feet(nodes.size());
    std::vector<Tensor<2, dim>> jacobians;
    if (!gradient_augmented)
      feet = midpoint_feet(fields, tau, locator, coarsened_detail);
    else
      {
        // Four-stage trace, with J = dX/dx for the gradient.
        const auto velocity_gradient = recover_nodal_gradients(fields, dim);
        std::vector<Tensor<1, dim>> k(nodes.size());
        std::vector<Tensor<2, dim>> dk(nodes.size());
        for (unsigned int i = 0; i < nodes.size(); ++i)
          {
            points[i] = nodes[i].point;
            k[i]      = fields.velocity(nodes[i]);
            for (unsigned int a = 0; a < dim; ++a)
              for (unsigned int b = 0; b < dim; ++b)
                dk[i][a][b] = velocity_gradient[b](nodes[i].dofs[a]);
          }
        four_stage_trace<dim>(fields,
                              velocity_gradient,
                              tau,
                              locator,
                              points,
                              k,
                              dk,
                              feet,
                              jacobians,
                              coarsened_detail);
      }

    std::vector<double> beyond_contact(nodes.size());
    for (unsigned int i = 0; i < nodes.size(); ++i)
      {
        beyond_contact[i] = locator.distance_beyond_contact_walls(feet[i]);
        points[i]         = locator.fold_into_cavity(feet[i]);
      }

    FieldHermite<dim> hermite;
    auto              how = level_set_interpolation(fields,
                                       level_set_gradient,
                                       interpolation.level_set,
                                       hermite);
    how.coarsened_detail  = coarsened_detail;
    // A cubic that overshoots its nodal values in a cell at a contact wall
    // lays liquid thinner than a cell along the wall, which the contact set
    // then holds: with any unlimited cubic level set the 3D ball's Stokes
    // solver stopped at its impact (doc/transport_in_flows.md, "What holds
    // it in flows").
    how.limited_at_contact_walls = &locator;
    std::vector<unsigned int> cubic_components;
    if (interpolation.velocity != VelocityInterpolation::linear)
      {
        for (unsigned int d = 0; d < dim; ++d)
          how.velocity_components.push_back(d);
        if (fields.has_acceleration())
          for (unsigned int d = 0; d < dim; ++d)
            how.velocity_components.push_back(
              fields.first_acceleration_component + d);
        cubic_components     = how.velocity_components;
        how.velocity_hermite = &hermite;
        how.velocity_limited =
          interpolation.velocity == VelocityInterpolation::limited_cubic;
      }
    if (interpolation.cubic_stress && fields.has_stress())
      {
        for (unsigned int i = 0;
             i < TransportedFields<dim>::n_stress_components;
             ++i)
          cubic_components.push_back(
            TransportedFields<dim>::first_stress_component + i);
        how.stress_hermite = &hermite;
        how.shear_modulus  = interpolation.shear_modulus;
      }
    if (!cubic_components.empty())
      hermite.recover_components(fields, cubic_components);
    auto at_feet = evaluate_at(points, fields, locator, how);
    // Liquid that leaves a contact wall leaves empty space behind: a foot
    // beyond the wall is that far outside the liquid.
    for (unsigned int i = 0; i < nodes.size(); ++i)
      if (beyond_contact[i] > 0)
        at_feet[i][TransportedFields<dim>::level_set_component] =
          std::max(at_feet[i][TransportedFields<dim>::level_set_component],
                   beyond_contact[i]);

    for (unsigned int i = 0; i < nodes.size(); ++i)
      for (unsigned int c = 0; c < fields.n_components; ++c)
        fields.set_value(nodes[i], c, at_feet[i][c]);

    if (gradient_augmented)
      for (unsigned int i = 0; i < nodes.size(); ++i)
        {
          // grad psi_new(x) = J^T grad psi_old(X(x)). Beyond a contact
          // wall psi_old is the wall's value, without a normal derivative:
          // carried along, the wall's normal derivative bends the Hermite
          // cubic of the cells at the wall as liquid climbs it (the seed's
          // soft ball: 16.5 % more liquid by t = 0.3 s without the volume
          // correction, 5.6 % without that derivative;
          // doc/transport_in_flows.md). Beyond a wall the liquid cannot leave,
          // a foot is a trace error and the gradient there extrapolates.
          const Tensor<2, dim> &J = jacobians[i];
          Tensor<1, dim>        old_gradient;
          for (unsigned int d = 0; d < dim; ++d)
            old_gradient[d] = at_feet[i].extra(d);
          level_set_gradient.set(
            nodes[i],
            locator.gradient_beyond_contact_walls(feet[i], old_gradient) * J);
        }
    fields.finalize();
    if (gradient_augmented)
      {
        // It reads the owned entries and makes the gradient consistent.
        // Bound 1: the drop into a pool keeps its energy falling, Zalesak's
        // disk and the vortex keep their shape errors (0.5 cost the disk
        // 8 %; doc/transport_in_flows.md).
        hold_gradient_to_values(fields, level_set_gradient, 1.);
      }
  }

  template <int dim>
  void
  trace_back(const TransportedFields<dim> &fields,
             const std::array<typename TransportedFields<dim>::VectorType, dim>
                                         &velocity_gradient,
             const double                 tau,
             const BoxMeshLocator<dim>   &locator,
             std::vector<Point<dim>>     &points,
             std::vector<Tensor<2, dim>> *jacobians,
             std::vector<double>         &beyond_contact)
  {
    Interpolation<dim> at_start;
    at_start.velocity_gradient = &velocity_gradient;
    const auto at_points       = evaluate_at(points, fields, locator, at_start);
    std::vector<Tensor<1, dim>> k(points.size());
    std::vector<Tensor<2, dim>> dk(points.size());
    for (unsigned int i = 0; i < points.size(); ++i)
      for (unsigned int a = 0; a < dim; ++a)
        {
          k[i][a] = at_points[i][a];
          for (unsigned int b = 0; b < dim; ++b)
            dk[i][a][b] = at_points[i].extra(dim * a + b);
        }
    std::vector<Point<dim>>     feet;
    std::vector<Tensor<2, dim>> step_jacobians;
    four_stage_trace<dim>(fields,
                          velocity_gradient,
                          tau,
                          locator,
                          points,
                          k,
                          dk,
                          feet,
                          step_jacobians,
                          nullptr);
    for (unsigned int i = 0; i < points.size(); ++i)
      {
        beyond_contact[i] =
          std::max(beyond_contact[i],
                   locator.distance_beyond_contact_walls(feet[i]));
        points[i] = locator.fold_into_cavity(feet[i]);
        // Chain rule: the newer steps were traced first.
        if (jacobians)
          (*jacobians)[i] = step_jacobians[i] * (*jacobians)[i];
      }
  }

  template <int dim>
  typename TransportedFields<dim>::VectorType
  predict_level_set(const TransportedFields<dim> &fields,
                    const double                  tau,
                    const BoxMeshLocator<dim>    &locator)
  {
    constexpr unsigned int  c     = TransportedFields<dim>::level_set_component;
    const auto             &nodes = fields.nodes();
    std::vector<Point<dim>> feet =
      midpoint_feet<dim>(fields, tau, locator, nullptr);
    std::vector<double> beyond_contact(nodes.size());
    for (unsigned int i = 0; i < nodes.size(); ++i)
      {
        beyond_contact[i] = locator.distance_beyond_contact_walls(feet[i]);
        feet[i]           = locator.fold_into_cavity(feet[i]);
      }
    const auto at_feet =
      evaluate_at(feet, fields, locator, Interpolation<dim>());

    typename TransportedFields<dim>::VectorType predicted;
    fields.initialize_vector(predicted);
    // As in the advection: only a foot beyond a contact wall is outside the
    // liquid by its distance. Elsewhere that distance is 0, and taking it
    // would lift psi to 0 in all the liquid: every liquid cell would look
    // cut and be refined before the advection.
    for (unsigned int i = 0; i < nodes.size(); ++i)
      predicted(nodes[i].dofs[c]) =
        beyond_contact[i] > 0 ? std::max(at_feet[i][c], beyond_contact[i])
                              : at_feet[i][c];
    fields.make_consistent(predicted);
    return predicted;
  }

  template <int dim>
  std::vector<std::pair<double, Tensor<1, dim>>>
  level_set_at(const TransportedFields<dim>  &fields,
               const LevelSetGradient<dim>   &level_set_gradient,
               const std::vector<Point<dim>> &points,
               const BoxMeshLocator<dim>     &locator,
               const LevelSetInterpolation    interpolation)
  {
    const bool gradient_augmented =
      interpolation == LevelSetInterpolation::gradient_augmented;
    FieldHermite<dim>                              hermite;
    const auto                                     values = evaluate_at(points,
                                    fields,
                                    locator,
                                    level_set_interpolation(fields,
                                                            level_set_gradient,
                                                            interpolation,
                                                            hermite));
    std::vector<std::pair<double, Tensor<1, dim>>> result(points.size());
    for (unsigned int i = 0; i < points.size(); ++i)
      {
        result[i].first =
          values[i][TransportedFields<dim>::level_set_component];
        if (gradient_augmented)
          for (unsigned int d = 0; d < dim; ++d)
            result[i].second[d] = values[i].extra(d);
      }
    return result;
  }

#define VEFS_INSTANTIATE(dim)                                                  \
  template void trace_back<dim>(                                               \
    const TransportedFields<dim> &,                                            \
    const std::array<typename TransportedFields<dim>::VectorType, dim> &,      \
    const double,                                                              \
    const BoxMeshLocator<dim> &,                                               \
    std::vector<Point<dim>> &,                                                 \
    std::vector<Tensor<2, dim>> *,                                             \
    std::vector<double> &);                                                    \
  template std::vector<std::pair<double, Tensor<1, dim>>> level_set_at<dim>(   \
    const TransportedFields<dim> &,                                            \
    const LevelSetGradient<dim> &,                                             \
    const std::vector<Point<dim>> &,                                           \
    const BoxMeshLocator<dim> &,                                               \
    const LevelSetInterpolation);                                              \
  template typename TransportedFields<dim>::VectorType predict_level_set<dim>( \
    const TransportedFields<dim> &,                                            \
    const double,                                                              \
    const BoxMeshLocator<dim> &);
  VEFS_INSTANTIATE(2)
  VEFS_INSTANTIATE(3)
#undef VEFS_INSTANTIATE

  template void
  advect_along_characteristics<2>(TransportedFields<2> &,
                                  LevelSetGradient<2> &,
                                  const double,
                                  const BoxMeshLocator<2> &,
                                  const FootInterpolation &,
                                  const CoarsenedDetail<2> *);
  template void
  advect_along_characteristics<3>(TransportedFields<3> &,
                                  LevelSetGradient<3> &,
                                  const double,
                                  const BoxMeshLocator<3> &,
                                  const FootInterpolation &,
                                  const CoarsenedDetail<3> *);
} // namespace vefs
