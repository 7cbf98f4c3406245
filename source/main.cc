#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <vefs/base/parameter_file.h>
#include <vefs/base/stop_signal.h>
#include <vefs/core/parameters.h>
#include <vefs/core/simulator.h>
#include <vefs/flow/stokes_step.h>
#include <vefs/io/checkpoint.h>

#include <chrono>
#include <iostream>
#include <sstream>
#include <thread>

namespace
{
  const char *usage =
    "Usage: vefs [options] [scene.prm]\n"
    "       vefs [options] --resume DIR\n"
    "\n"
    "Simulates the free-surface flow described by scene.prm (deal.II\n"
    "ParameterHandler format). Without a file, runs the default scene: the\n"
    "2D broken dam of Martin & Moyce (1952), writing into ./output/.\n"
    "Run in parallel with: mpirun -np N vefs scene.prm\n"
    "\n"
    "Options:\n"
    "  -h, --help            this text\n"
    "  --print-parameters    every entry with its default and documentation\n"
    "  --resume DIR          continue the run whose output directory is DIR\n"
    "                        from its last checkpoint (DIR/checkpoint/), with\n"
    "                        the parameters saved there, on any number of\n"
    "                        ranks\n";

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
   * An error vefs does not expect (a deal.II or standard exception) may be
   * thrown on one rank alone, while the others wait for it in a collective
   * call for ever. If all ranks report one within a minute, the run ends
   * with the message like any other error; otherwise this rank prints it
   * and aborts them all. @p errors: a copy of MPI_COMM_WORLD kept for this,
   * so that the check cannot meet a collective call of the run.
   */
  vefs::RunEnd
  unexpected_error(const std::string &message, const MPI_Comm errors)
  {
    if (dealii::Utilities::MPI::n_mpi_processes(errors) == 1)
      return {1, message};
    MPI_Request all_failed;
    MPI_Ibarrier(errors, &all_failed);
    const auto start = std::chrono::steady_clock::now();
    int        done  = 0;
    while (!done &&
           std::chrono::steady_clock::now() - start < std::chrono::seconds(60))
      {
        MPI_Test(&all_failed, &done, MPI_STATUS_IGNORE);
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
      }
    if (done)
      return {1, message};
    std::cerr << "vefs: rank "
              << dealii::Utilities::MPI::this_mpi_process(errors)
              << " alone: " << message << std::endl;
    MPI_Abort(MPI_COMM_WORLD, 1);
    return {1, message};
  }

  /**
   * Run the scene; returns how it ended, with status 1 and the error if
   * one stopped it. The error is caught while the simulator still exists,
   * so that it closes normally (its timer would otherwise complain about
   * unwinding).
   */
  template <int dim>
  vefs::RunEnd
  simulate(const vefs::Parameters         &parameters,
           const dealii::ParameterHandler &prm,
           const std::string              &where,
           const std::string              &checkpoint,
           const MPI_Comm                  errors)
  {
    vefs::Simulator<dim> simulator(parameters, prm, checkpoint);
    try
      {
        return simulator.run();
      }
    catch (const vefs::InputError &error)
      {
        return {1, "error in " + where + ": " + error.what()};
      }
    catch (const vefs::SolverError &error)
      {
        return {1, error.what()};
      }
    catch (const vefs::CheckpointError &error)
      {
        return {1, error.what()};
      }
    catch (const vefs::OutputError &error)
      {
        return {1, error.what()};
      }
    catch (const dealii::ExceptionBase &error)
      {
        return unexpected_error(message_of(error), errors);
      }
    catch (const std::exception &error)
      {
        return unexpected_error(error.what(), errors);
      }
  }
} // namespace

int
main(int argc, char *argv[])
{
  using namespace dealii;
  using namespace vefs;

  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  MPI_Comm                         errors;
  MPI_Comm_dup(MPI_COMM_WORLD, &errors);
  const bool  root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  std::string file, resume_directory;
  auto        fail = [&](const std::string &what) {
    if (root)
      std::cerr << "vefs: " << what << std::endl;
    return 1;
  };

  // The entries are bound to the members of parameters (add_parameter).
  Parameters       parameters;
  ParameterHandler prm;
  parameters.declare(prm);
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
      if (argument == "--resume")
        {
          if (i + 1 == argc)
            return fail("option --resume needs the output directory of the "
                        "run to continue\n" +
                        std::string(usage));
          resume_directory = argv[++i];
          continue;
        }
      if (!argument.empty() && argument[0] == '-')
        return fail("unknown option '" + argument + "'\n" + usage);
      if (!file.empty())
        return fail("more than one parameter file given\n" +
                    std::string(usage));
      file = argument;
    }

  if (!resume_directory.empty() && !file.empty())
    return fail("option --resume takes the parameters from the checkpoint: "
                "give no parameter file");
  std::string checkpoint;
  if (!resume_directory.empty())
    {
      try
        {
          checkpoint = find_checkpoint(resume_directory, MPI_COMM_WORLD);
        }
      catch (const InputError &error)
        {
          return fail(error.what());
        }
      file = checkpoint + "/parameters.prm";
    }

  const std::string where =
    file.empty() ? "default parameters" : "'" + file + "'";
  try
    {
      std::vector<std::string> file_warnings;
      if (!file.empty())
        file_warnings =
          read_parameter_file(prm, file, Parameters::moved_entries);
      // The directory may have moved since the checkpoint.
      if (!resume_directory.empty())
        prm.set("Output directory", resume_directory);
      parameters.check();
      file_warnings.insert(file_warnings.end(),
                           parameters.warnings.begin(),
                           parameters.warnings.end());
      if (root)
        for (const auto &warning : file_warnings)
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

  install_stop_handlers();
  try
    {
      const RunEnd end =
        parameters.dimension == 2
          ? simulate<2>(parameters, prm, where, checkpoint, errors)
          : simulate<3>(parameters, prm, where, checkpoint, errors);
      if (end.status != 0)
        {
          fail(end.message);
          return end.status;
        }
      if (root && !end.message.empty())
        std::cout << "vefs: " << end.message << std::endl;
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
