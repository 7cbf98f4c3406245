#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_postprocessor.h>

#include <vefs/base/errors.h>
#include <vefs/base/write_failure.h>
#include <vefs/io/visualization.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace vefs
{
  namespace
  {
    /** phi = H(-psi) at the output points: the liquid indicator. */
    template <int dim>
    class LiquidIndicator : public DataPostprocessorScalar<dim>
    {
    public:
      LiquidIndicator()
        : DataPostprocessorScalar<dim>("phi", update_values)
      {
      }

      void
      evaluate_vector_field(
        const DataPostprocessorInputs::Vector<dim> &inputs,
        std::vector<Vector<double>> &computed_quantities) const override
      {
        for (unsigned int q = 0; q < inputs.solution_values.size(); ++q)
          computed_quantities[q](0) =
            inputs.solution_values
                  [q][TransportedFields<dim>::level_set_component] < 0
              ? 1.
              : 0.;
      }
    };

    /** sigma_xx - sigma_yy: the first normal stress difference. */
    template <int dim>
    class FirstNormalStressDifference : public DataPostprocessorScalar<dim>
    {
    public:
      FirstNormalStressDifference()
        : DataPostprocessorScalar<dim>("first_normal_stress_difference",
                                       update_values)
      {
      }

      void
      evaluate_vector_field(
        const DataPostprocessorInputs::Vector<dim> &inputs,
        std::vector<Vector<double>> &computed_quantities) const override
      {
        // Unrolled order: xx, yy, ...
        constexpr unsigned int first =
          TransportedFields<dim>::first_stress_component;
        for (unsigned int q = 0; q < inputs.solution_values.size(); ++q)
          computed_quantities[q](0) = inputs.solution_values[q][first] -
                                      inputs.solution_values[q][first + 1];
      }
    };

    /** Names of the stress components, in unrolled order. */
    template <int dim>
    std::vector<std::string>
    stress_names()
    {
      if (dim == 2)
        return {"sigma_xx", "sigma_yy", "sigma_xy"};
      return {"sigma_xx",
              "sigma_yy",
              "sigma_zz",
              "sigma_xy",
              "sigma_xz",
              "sigma_yz"};
    }

    /**
     * The components of the fields before the dumbbells' (all of them
     * without dumbbells): N_f configuration fields are too many to write.
     */
    template <int dim>
    class FieldsBeforeDumbbells : public DataPostprocessor<dim>
    {
    public:
      FieldsBeforeDumbbells(
        const std::vector<std::string> &names,
        const std::vector<
          DataComponentInterpretation::DataComponentInterpretation>
          &interpretation)
        : names(names)
        , interpretation(interpretation)
      {
      }

      void
      evaluate_vector_field(
        const DataPostprocessorInputs::Vector<dim> &inputs,
        std::vector<Vector<double>> &computed_quantities) const override
      {
        for (unsigned int q = 0; q < inputs.solution_values.size(); ++q)
          for (unsigned int c = 0; c < names.size(); ++c)
            computed_quantities[q](c) = inputs.solution_values[q][c];
      }

      std::vector<std::string>
      get_names() const override
      {
        return names;
      }

      std::vector<DataComponentInterpretation::DataComponentInterpretation>
      get_data_component_interpretation() const override
      {
        return interpretation;
      }

      UpdateFlags
      get_needed_update_flags() const override
      {
        return update_values;
      }

    private:
      const std::vector<std::string> names;
      const std::vector<
        DataComponentInterpretation::DataComponentInterpretation>
        interpretation;
    };
  } // namespace

  template <int dim>
  Visualization<dim>::Visualization(const std::string &directory)
    : directory(directory)
  {
  }

  template <int dim>
  void
  Visualization<dim>::write(const TransportedFields<dim> &fields,
                            const StokesStep<dim>        &flow,
                            const Vector<float>          &liquid_fraction,
                            const unsigned int            step,
                            const double                  time)
  {
    const auto    &triangulation = fields.dof_handler.get_triangulation();
    const MPI_Comm comm          = triangulation.get_communicator();

    DataOut<dim> data_out;
    data_out.attach_triangulation(triangulation);

    std::vector<std::string> names(dim, "extended_velocity");
    names.push_back("level_set");
    std::vector<DataComponentInterpretation::DataComponentInterpretation>
      interpretation(dim,
                     DataComponentInterpretation::component_is_part_of_vector);
    interpretation.push_back(DataComponentInterpretation::component_is_scalar);
    std::vector<DataComponentInterpretation::DataComponentInterpretation>
      field_interpretation = interpretation;
    if (fields.has_stress())
      for (const auto &name : stress_names<dim>())
        {
          names.push_back(name);
          field_interpretation.push_back(
            DataComponentInterpretation::component_is_scalar);
        }
    if (fields.has_acceleration())
      for (unsigned int d = 0; d < dim; ++d)
        {
          names.push_back("acceleration");
          field_interpretation.push_back(
            DataComponentInterpretation::component_is_part_of_vector);
        }
    const FieldsBeforeDumbbells<dim> fields_before_dumbbells(
      names,
      field_interpretation);
    if (fields.n_dumbbell_fields > 0)
      data_out.add_data_vector(fields.dof_handler,
                               fields.vector(),
                               fields_before_dumbbells);
    else
      data_out.add_data_vector(fields.dof_handler,
                               fields.vector(),
                               names,
                               field_interpretation);

    const LiquidIndicator<dim> phi;
    data_out.add_data_vector(fields.dof_handler, fields.vector(), phi);
    const FirstNormalStressDifference<dim> first_normal_stress_difference;
    if (fields.has_stress())
      data_out.add_data_vector(fields.dof_handler,
                               fields.vector(),
                               first_normal_stress_difference);

    if (flow.n_dofs() > 0)
      {
        std::vector<std::string> flow_names(dim, "velocity");
        flow_names.push_back("pressure");
        data_out.add_data_vector(flow.get_dof_handler(),
                                 flow.get_solution(),
                                 flow_names,
                                 interpretation);
      }

    Vector<float> rank_of_cell(triangulation.n_active_cells());
    rank_of_cell = Utilities::MPI::this_mpi_process(comm);
    data_out.add_data_vector(liquid_fraction, "liquid_fraction");
    data_out.add_data_vector(rank_of_cell, "mpi_rank");
    data_out.build_patches();

    // The names of DataOut::write_vtu_with_pvtu_record(), whose writes
    // are not checked: a full disk would leave truncated files and the run
    // would go on.
    const unsigned int rank    = Utilities::MPI::this_mpi_process(comm);
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
    const std::string  stem =
      "solution_" + Utilities::int_to_string(series.size(), 5);
    const auto piece = [&](const unsigned int r) {
      return stem + "." +
             Utilities::int_to_string(r,
                                      Utilities::needed_digits(n_ranks - 1)) +
             ".vtu";
    };
    const std::string name = stem + ".pvtu";
    std::string       problem =
      checked_write(directory + "/" + piece(rank),
                    [&](std::ostream &out) { data_out.write_vtu(out); });
    if (rank == 0 && problem.empty())
      {
        std::vector<std::string> pieces;
        for (unsigned int r = 0; r < n_ranks; ++r)
          pieces.push_back(piece(r));
        problem = checked_write(directory + "/" + name, [&](std::ostream &out) {
          data_out.write_pvtu_record(out, pieces);
        });
      }
    std::ostringstream where;
    where << "after step " << step << " (t = " << time << ")";
    // The series names the file only once every piece is written.
    throw_if_write_failed(problem, where.str(), comm);
    series.emplace_back(time, name);
    // Written anew and renamed: a failed write keeps the series so far.
    if (rank == 0)
      {
        const std::string pvd = directory + "/solution.pvd";
        problem = checked_write(pvd + ".new", [&](std::ostream &out) {
          DataOutBase::write_pvd_record(out, series);
        });
        std::error_code error;
        if (problem.empty())
          std::filesystem::rename(pvd + ".new", pvd, error);
        else
          std::filesystem::remove(pvd + ".new", error);
        if (problem.empty() && error)
          problem = "cannot replace '" + pvd + "': " + error.message();
      }
    try
      {
        throw_if_write_failed(problem, where.str(), comm);
      }
    catch (const OutputError &)
      {
        series.pop_back();
        throw;
      }
  }

  template class Visualization<2>;
  template class Visualization<3>;
} // namespace vefs
