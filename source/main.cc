#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <vefs/parameter_file.h>
#include <vefs/parameters.h>
#include <vefs/simulator.h>
#include <vefs/stokes_step.h>

#include <iostream>
#include <sstream>

namespace
{
  const char *usage =
    "Usage: vefs [options] [scene.prm]\n"
    "\n"
    "Simulates the free-surface flow described by scene.prm (deal.II\n"
    "ParameterHandler format). Without a file, runs the default scene: the\n"
    "2D broken dam of Martin & Moyce (1952), writing into ./output/.\n"
    "Run in parallel with: mpirun -np N vefs scene.prm\n"
    "\n"
    "Options:\n"
    "  -h, --help            this text\n"
    "  --print-parameters    every entry with its default and documentation\n";

  /** The text a deal.II exception carries for the user, without its trace. */
  std::string
  message_of(const dealii::ExceptionBase &exception)
  {
    std::ostringstream text;
    exception.print_info(text);
    std::string message = text.str();
    while (!message.empty() && std::isspace(message.back()))
      message.pop_back();
    const auto start = message.find_first_not_of(" \n");
    return start == std::string::npos ? message : message.substr(start);
  }

  /**
   * Run the scene; returns the error that stopped it, or nothing. The
   * error is caught while the simulator still exists, so that it closes
   * normally (its timer would otherwise complain about unwinding).
   */
  template <int dim>
  std::string
  simulate(const vefs::Parameters         &parameters,
           const dealii::ParameterHandler &prm,
           const std::string              &where)
  {
    vefs::Simulator<dim> simulator(parameters, prm);
    try
      {
        simulator.run();
      }
    catch (const vefs::InputError &error)
      {
        return "error in " + where + ": " + error.what();
      }
    catch (const vefs::SolverError &error)
      {
        return error.what();
      }
    catch (const dealii::ExceptionBase &error)
      {
        return message_of(error);
      }
    catch (const std::exception &error)
      {
        return error.what();
      }
    return "";
  }
} // namespace

int
main(int argc, char *argv[])
{
  using namespace dealii;
  using namespace vefs;

  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool  root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  std::string file;
  auto        fail = [&](const std::string &what) {
    if (root)
      std::cerr << "vefs: " << what << std::endl;
    return 1;
  };

  ParameterHandler prm;
  Parameters::declare(prm);
  for (int i = 1; i < argc; ++i)
    {
      const std::string argument = argv[i];
      if (argument == "-h" || argument == "--help")
        {
          if (root)
            std::cout << usage;
          return 0;
        }
      if (argument == "--print-parameters")
        {
          if (root)
            prm.print_parameters(std::cout, ParameterHandler::PRM);
          return 0;
        }
      if (!argument.empty() && argument[0] == '-')
        return fail("unknown option '" + argument + "'\n" + usage);
      if (!file.empty())
        return fail("more than one parameter file given\n" +
                    std::string(usage));
      file = argument;
    }

  const std::string where =
    file.empty() ? "default parameters" : "'" + file + "'";
  Parameters parameters;
  try
    {
      if (!file.empty())
        {
          check_parameter_file(file);
          prm.parse_input(file);
        }
      parameters.parse(prm);
      if (root)
        for (const auto &warning : parameters.warnings)
          std::cerr << "vefs: warning in " << where << ": " << warning
                    << std::endl;
      parameters.check_for_ranks(
        Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD));
    }
  catch (const InputError &error)
    {
      return fail("error in " + where + ": " + error.what());
    }
  catch (const ExceptionBase &error)
    {
      return fail("error in " + where + ": " + message_of(error));
    }

  try
    {
      const std::string error = parameters.dimension == 2
                                  ? simulate<2>(parameters, prm, where)
                                  : simulate<3>(parameters, prm, where);
      if (!error.empty())
        return fail(error);
    }
  catch (const InputError &error)
    {
      return fail("error in " + where + ": " + error.what());
    }
  catch (const SolverError &error)
    {
      return fail(error.what());
    }
  catch (const ExceptionBase &error)
    {
      return fail(message_of(error));
    }
  catch (const std::exception &error)
    {
      return fail(error.what());
    }
  return 0;
}
