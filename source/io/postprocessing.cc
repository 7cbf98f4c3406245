#include <deal.II/base/quadrature_lib.h>

#include <vefs/base/parameter_entries.h>
#include <vefs/io/postprocessing.h>
#include <vefs/io/shadow_holes.h>
#include <vefs/stress/mechanical_energy.h>
#include <vefs/transport/free_surface.h>

#include <array>
#include <cmath>
#include <limits>

namespace vefs
{
  namespace
  {
    /**
     * Widen the box [lower, upper] to the liquid of @p cell: all vertices of
     * a full cell; of a cut one, its liquid vertices and the quadrature
     * points of its piece of surface (the box is then short of the surface's
     * extreme by a fraction of the piece, well below a cell).
     */
    template <int dim, typename CellIterator>
    void
    widen_to_liquid(const CellIterator           &cell,
                    const TransportedFields<dim> &fields,
                    const LiquidDomain<dim>      &domain,
                    Point<dim>                   &lower,
                    Point<dim>                   &upper)
    {
      const auto include = [&](const Point<dim> &p) {
        for (unsigned int d = 0; d < dim; ++d)
          {
            lower[d] = std::min(lower[d], p[d]);
            upper[d] = std::max(upper[d], p[d]);
          }
      };
      const bool is_cut =
        domain.location(cell) == LiquidDomain<dim>::Location::cut;
      for (const unsigned int v : cell->vertex_indices())
        if (!is_cut || fields.level_set_at(cell, v) <= 0)
          include(cell->vertex(v));
      if (is_cut)
        {
          // The cells are boxes: the reference cell maps by a diagonal
          // scaling.
          const Point<dim> origin   = cell->vertex(0);
          const Point<dim> diagonal = cell->vertex(cell->n_vertices() - 1);
          for (const Point<dim> &xi :
               domain.cut_cell(cell).surface.get_points())
            {
              Point<dim> p = origin;
              for (unsigned int d = 0; d < dim; ++d)
                p[d] += xi[d] * (diagonal[d] - origin[d]);
              include(p);
            }
        }
    }
  } // namespace

  void
  PostprocessParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Postprocess");
    {
      prm.add_parameter("Probe point",
                        probe_point,
                        "If not empty, a point (m) of the cavity where the "
                        "velocity is written to the statistics every step "
                        "(columns probe_u_x, probe_u_y, probe_u_z).",
                        Patterns::List(Patterns::Double(), 0, 3));
      prm.add_parameter(
        "Energy budget",
        energy_budget,
        "If true (flows only), the statistics hold what each stage of a step "
        "adds to the total energy (kinetic + potential + elastic, J or J/m "
        "in 2D): energy_change_transport (advection, mesh adaptation, "
        "redistancing, volume correction), energy_change_flow (the flow "
        "step with its contact iterations and the stress update) and "
        "energy_change_extension (the velocity and stress beyond the "
        "liquid, which reach into the cut cells). Without viscosity, "
        "moving walls or open walls, their sum is the energy the scheme "
        "adds or removes. Parts of energy_change_flow: with contact walls "
        "energy_change_contact, the work of their new reactions over the "
        "step; with a stress energy_change_stress_update, what the stress "
        "update at the nodes adds beyond the same update at the flow "
        "step's quadrature points. Costs three integrals over the liquid "
        "per step, four with a stress.",
        Patterns::Bool());
    }
    prm.leave_subsection();
  }

  void
  PostprocessParameters::check(const unsigned int      dimension,
                               const CavityParameters &cavity) const
  {
    require(probe_point.empty() || probe_point.size() == dimension,
            "Postprocess/Probe point",
            "needs " + std::to_string(dimension) +
              " comma-separated numbers or nothing");
    for (unsigned int d = 0; d < probe_point.size(); ++d)
      require(probe_point[d] >= cavity.cavity_lower[d] &&
                probe_point[d] <= cavity.cavity_upper[d],
              "Postprocess/Probe point",
              "must lie inside the cavity");
  }

  template <int dim>
  void
  measure_step(const MaterialParameters     &material,
               const CavityParameters       &cavity,
               const TransportedFields<dim> &fields,
               const LiquidDomain<dim>      &domain,
               const double                  initial_volume,
               const double                  expected_volume,
               StepStatistics<dim>          &s)
  {
    const MPI_Comm comm =
      fields.dof_handler.get_triangulation().get_communicator();
    Tensor<1, dim> gravity;
    for (unsigned int d = 0; d < dim; ++d)
      gravity[d] = material.gravity[d];

    // Volume, centroid and energies over the liquid as the flow step sees it.
    LiquidValues<dim> liquid_values(domain);
    std::array<Tensor<1, dim>, GeometryInfo<dim>::vertices_per_cell> vertex_u;

    double         kinetic = 0, potential = 0, volume = 0, max_speed = 0;
    Tensor<1, dim> first_moment, momentum;
    unsigned int   liquid_cells = 0;
    Point<dim>     lower, upper;
    for (unsigned int d = 0; d < dim; ++d)
      {
        lower[d] = std::numeric_limits<double>::max();
        upper[d] = -std::numeric_limits<double>::max();
      }
    for (const auto &cell : fields.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && domain.has_liquid(cell))
        {
          ++liquid_cells;
          widen_to_liquid(cell, fields, domain, lower, upper);
          for (const unsigned int v : cell->vertex_indices())
            {
              vertex_u[v] = fields.velocity_at(cell, v);
              max_speed   = std::max(max_speed, vertex_u[v].norm());
            }
          const BoxCellValues<dim> &values = liquid_values.reinit(cell);
          for (unsigned int q = 0; q < values.size(); ++q)
            {
              const Tensor<1, dim> u = values.value(vertex_u, q);
              volume += values.JxW[q];
              first_moment += values.JxW[q] * values.point[q];
              momentum += values.JxW[q] * u;
              kinetic +=
                kinetic_energy_density(material.density, u) * values.JxW[q];
              potential += potential_energy_density(material.density,
                                                    gravity,
                                                    values.point[q]) *
                           values.JxW[q];
            }
        }
    s.kinetic_energy    = Utilities::MPI::sum(kinetic, comm);
    s.potential_energy  = Utilities::MPI::sum(potential, comm);
    s.elastic_energy    = 0;
    s.volume            = Utilities::MPI::sum(volume, comm);
    s.volume_change     = (s.volume - expected_volume) / initial_volume;
    s.centroid          = Utilities::MPI::sum(first_moment, comm) / s.volume;
    s.centroid_velocity = Utilities::MPI::sum(momentum, comm) / s.volume;
    s.liquid_cells      = Utilities::MPI::sum(liquid_cells, comm);
    s.max_velocity      = Utilities::MPI::max(max_speed, comm);
    for (unsigned int d = 0; d < dim; ++d)
      {
        s.liquid_lower[d] = Utilities::MPI::min(lower[d], comm);
        s.liquid_upper[d] = Utilities::MPI::max(upper[d], comm);
      }

    const unsigned int vertical = dim - 1;
    s.floor_extent =
      liquid_extent_on_wall(fields, 2 * vertical, 0, cavity.cavity_lower[0]);
    s.wall_height =
      liquid_extent_on_wall(fields, 0, vertical, cavity.cavity_lower[vertical]);
    s.shadow_holes = shadow_holes(fields, cavity);
    s.cells = fields.dof_handler.get_triangulation().n_global_active_cells();
  }

  template <int dim>
  Probe<dim>
  probe_velocity(const TransportedFields<dim> &fields,
                 const BoxMeshLocator<dim>    &locator,
                 const Point<dim>             &point,
                 const double                  shear_modulus)
  {
    // Exactly one rank owns the cell the locator finds. Components 0 to
    // dim - 1: the velocity; dim: the level set; then the stress (if any),
    // and with dumbbells the mean square of each field's q_a q_b (less its
    // equilibrium field's p_a p_b, with variance reduction) less the square
    // of their mean: the variance over the fields.
    constexpr unsigned int n_stress =
      TransportedFields<dim>::n_stress_components;
    const unsigned int  first_stress = dim + 1;
    const unsigned int  first_spread = first_stress + n_stress;
    std::vector<double> values(first_spread + n_stress);
    const auto          cell = locator.locate(point);
    if (cell->is_locally_owned())
      {
        const Point<dim>   xi = BoxMeshLocator<dim>::unit_point(cell, point);
        const auto         dof_cell = fields.cell_of(cell);
        const unsigned int n_fields = fields.n_dumbbell_fields;
        std::vector<SymmetricTensor<2, dim>> products(n_fields);
        for (const unsigned int v : cell->vertex_indices())
          {
            const double weight = BoxMeshLocator<dim>::vertex_weight(xi, v);
            for (unsigned int d = 0; d <= dim; ++d)
              values[d] += weight * fields.value_at(dof_cell, v, d);
            if (fields.has_stress())
              for (unsigned int i = 0; i < n_stress; ++i)
                values[first_stress + i] +=
                  weight *
                  fields.value_at(
                    dof_cell,
                    v,
                    TransportedFields<dim>::first_stress_component + i);
            for (unsigned int f = 0; f < n_fields; ++f)
              products[f] +=
                weight *
                symmetrize(outer_product(fields.dumbbell_at(dof_cell, v, f),
                                         fields.dumbbell_at(dof_cell, v, f)));
          }
        for (unsigned int f = 0; f < fields.dumbbell_controls.size(); ++f)
          products[f] -= symmetrize(outer_product(fields.dumbbell_controls[f],
                                                  fields.dumbbell_controls[f]));
        if (n_fields > 1)
          {
            SymmetricTensor<2, dim> mean, square;
            for (const auto &p : products)
              for (unsigned int i = 0; i < n_stress; ++i)
                {
                  mean.access_raw_entry(i) += p.access_raw_entry(i) / n_fields;
                  square.access_raw_entry(i) +=
                    p.access_raw_entry(i) * p.access_raw_entry(i) / n_fields;
                }
            for (unsigned int i = 0; i < n_stress; ++i)
              {
                const double m = mean.access_raw_entry(i);
                // The sample variance, (N / (N - 1)) (<p^2> - <p>^2).
                values[first_spread + i] =
                  std::max(0., square.access_raw_entry(i) - m * m) * n_fields /
                  (n_fields - 1.);
              }
          }
      }
    // deal.II instantiates the sum of tensors of dimension up to 3 only.
    MPI_Allreduce(MPI_IN_PLACE,
                  values.data(),
                  values.size(),
                  MPI_DOUBLE,
                  MPI_SUM,
                  fields.dof_handler.get_triangulation().get_communicator());
    static_assert(TransportedFields<dim>::level_set_component == dim);
    Probe<dim> probe;
    for (unsigned int d = 0; d < dim; ++d)
      probe.velocity[d] = values[d];
    probe.in_liquid = values[dim] < 0;
    for (unsigned int i = 0; i < n_stress; ++i)
      {
        probe.stress.access_raw_entry(i) = values[first_stress + i];
        if (fields.n_dumbbell_fields > 1)
          probe.stress_error.access_raw_entry(i) =
            shear_modulus *
            std::sqrt(values[first_spread + i] / fields.n_dumbbell_fields);
      }
    return probe;
  }

  template void
  measure_step<2>(const MaterialParameters &,
                  const CavityParameters &,
                  const TransportedFields<2> &,
                  const LiquidDomain<2> &,
                  const double,
                  const double,
                  StepStatistics<2> &);
  template void
  measure_step<3>(const MaterialParameters &,
                  const CavityParameters &,
                  const TransportedFields<3> &,
                  const LiquidDomain<3> &,
                  const double,
                  const double,
                  StepStatistics<3> &);
  template Probe<2>
  probe_velocity<2>(const TransportedFields<2> &,
                    const BoxMeshLocator<2> &,
                    const Point<2> &,
                    const double);
  template Probe<3>
  probe_velocity<3>(const TransportedFields<3> &,
                    const BoxMeshLocator<3> &,
                    const Point<3> &,
                    const double);
} // namespace vefs
