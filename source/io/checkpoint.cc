#include <deal.II/base/mpi.h>
#include <deal.II/distributed/solution_transfer.h>

#include <vefs/base/write_failure.h>
#include <vefs/io/abort_guard.h>
#include <vefs/io/checkpoint.h>
#include <vefs/io/output_directory.h>

#include <algorithm>
#include <cerrno>
#include <cinttypes>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>

namespace vefs
{
  namespace
  {
    namespace fs = std::filesystem;

    /**
     * First line of the state file; the number changes with its format.
     * Format 3 ends with a line "checksum HEX" of the bytes before it;
     * format 2 (without it) is still read.
     */
    const std::string magic   = "vefs checkpoint 3";
    const std::string magic_2 = "vefs checkpoint 2";

    /** Exactly, as a C99 hexadecimal float. */
    std::string
    exact(const double value)
    {
      char text[64];
      std::snprintf(text, sizeof(text), "%a", value);
      return text;
    }

    const std::uint64_t fnv_offset = 14695981039346656037ull;

    /** FNV-1a, continued from @p hash over @p n bytes. */
    std::uint64_t
    fnv1a(std::uint64_t hash, const char *bytes, const std::size_t n)
    {
      for (std::size_t i = 0; i < n; ++i)
        {
          hash ^= static_cast<unsigned char>(bytes[i]);
          hash *= 1099511628211ull;
        }
      return hash;
    }

    std::string
    hex(const std::uint64_t hash)
    {
      char text[32];
      std::snprintf(text, sizeof(text), "%016" PRIx64, hash);
      return text;
    }

    /** FNV-1a of the file's bytes: catches a truncated or damaged file. */
    std::uint64_t
    checksum(const std::string &file)
    {
      std::ifstream     input(file, std::ios::binary);
      std::uint64_t     hash = fnv_offset;
      std::vector<char> buffer(1 << 20);
      while (input)
        {
          input.read(buffer.data(), buffer.size());
          hash = fnv1a(hash, buffer.data(), input.gcount());
        }
      return hash;
    }

    /** The state text with its own checksum as the last line. */
    std::string
    sealed(const std::string &text)
    {
      return text + "checksum " +
             hex(fnv1a(fnv_offset, text.data(), text.size())) + '\n';
    }

    /**
     * The state text without its checksum line, after checking it: a byte
     * flip that leaves valid numbers (a step, a time) is caught here.
     */
    std::string
    unsealed(const std::string &text)
    {
      if (text.compare(0, magic_2.size() + 1, magic_2 + '\n') == 0)
        return text;
      if (text.compare(0, magic.size() + 1, magic + '\n') != 0)
        throw std::runtime_error("'state' does not start with '" + magic + "'");
      const std::string key    = "checksum ";
      const std::size_t length = key.size() + 16 + 1;
      if (text.size() <= length || text.back() != '\n' ||
          text.compare(text.size() - length, key.size(), key) != 0 ||
          text[text.size() - length - 1] != '\n')
        throw std::runtime_error("'state' does not end with its checksum");
      const std::size_t start = text.size() - length;
      const std::string body  = text.substr(0, start);
      if (text.substr(start + key.size(), 16) !=
          hex(fnv1a(fnv_offset, body.data(), body.size())))
        throw std::runtime_error(
          "'state' is damaged (its checksum differs from the one recorded)");
      return body;
    }

    /** "file NAME SIZE CHECKSUM" for each file but the state itself. */
    std::string
    file_lines(const std::string &directory)
    {
      std::vector<std::string> names;
      for (const auto &file : fs::directory_iterator(directory))
        if (file.is_regular_file() && file.path().filename() != "state")
          names.push_back(file.path().filename().string());
      std::sort(names.begin(), names.end());
      std::ostringstream lines;
      for (const auto &name : names)
        {
          const std::string path = directory + "/" + name;
          lines << "file " << name << ' ' << fs::file_size(path) << ' '
                << hex(checksum(path)) << '\n';
        }
      return lines.str();
    }

    /** The key-value lines of a state file. */
    using Entries = std::multimap<std::string, std::vector<std::string>>;

    Entries
    parse_entries(const std::string &text)
    {
      Entries            entries;
      std::istringstream input(text);
      std::string        line;
      std::getline(input, line);
      if (line != magic && line != magic_2)
        throw std::runtime_error("'state' does not start with '" + magic + "'");
      bool complete = false;
      while (std::getline(input, line))
        {
          if (complete)
            throw std::runtime_error("'state' has lines after its end");
          std::istringstream       words(line);
          std::string              key, word;
          std::vector<std::string> values;
          words >> key;
          while (words >> word)
            values.push_back(word);
          if (key == "end")
            complete = true;
          else if (!key.empty())
            entries.emplace(key, values);
        }
      if (!complete)
        throw std::runtime_error("'state' is incomplete");
      return entries;
    }

    const std::vector<std::string> &
    entry(const Entries &entries, const std::string &key)
    {
      const auto found = entries.find(key);
      if (found == entries.end() || found->second.empty())
        throw std::runtime_error("'state' has no value of '" + key + "'");
      return found->second;
    }

    double
    to_double(const std::string &text)
    {
      char        *end   = nullptr;
      const double value = std::strtod(text.c_str(), &end);
      if (text.empty() || *end != '\0')
        throw std::runtime_error("'state' has the malformed number '" + text +
                                 "'");
      return value;
    }

    unsigned long long
    to_unsigned(const std::string &text)
    {
      if (text.empty() ||
          text.find_first_not_of("0123456789") != std::string::npos)
        throw std::runtime_error("'state' has the malformed count '" + text +
                                 "'");
      return std::stoull(text);
    }

    /** Rank 0: the state text, after checking every file it lists. */
    std::string
    read_and_verify(const std::string &directory)
    {
      std::ifstream input(directory + "/state", std::ios::binary);
      if (!input)
        throw std::runtime_error("'state' is missing");
      std::ostringstream whole;
      whole << input.rdbuf();
      const std::string text    = unsealed(whole.str());
      const Entries     entries = parse_entries(text);
      if (entries.count("file") == 0)
        throw std::runtime_error("'state' lists no files");
      for (auto [it, end] = entries.equal_range("file"); it != end; ++it)
        {
          const auto &values = it->second;
          if (values.size() != 3)
            throw std::runtime_error("'state' has a malformed file line");
          const std::string path = directory + "/" + values[0];
          std::error_code   error;
          const auto        size = fs::file_size(path, error);
          if (error)
            throw std::runtime_error("'" + values[0] + "' is missing");
          if (size != to_unsigned(values[1]) ||
              values[2] != hex(checksum(path)))
            throw std::runtime_error("'" + values[0] +
                                     "' is damaged (its size or checksum "
                                     "differs from the one recorded)");
        }
      return text;
    }
  } // namespace

  std::string
  find_checkpoint(const std::string &output_directory, const MPI_Comm comm)
  {
    // Rank 0 reads; every rank gets its verdict.
    std::string found, warning, problem;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        const std::string current =
          output_directory + "/" + CheckpointNames::current;
        const std::string previous =
          output_directory + "/" + CheckpointNames::previous;
        std::string damaged;
        if (fs::exists(current))
          try
            {
              read_and_verify(current);
              found = current;
            }
          catch (const std::exception &error)
            {
              damaged =
                "the checkpoint '" + current + "' is unusable: " + error.what();
            }
        // checkpoint.old/: the one before (README, "Checkpoint and
        // restart"), or the only one if a kill fell between the renames.
        if (found.empty() && fs::exists(previous))
          try
            {
              read_and_verify(previous);
              found = previous;
              if (!damaged.empty())
                warning =
                  damaged + "; resumed from the one before, '" + previous + "'";
            }
          catch (const std::exception &error)
            {
              damaged += (damaged.empty() ? "" : "; ") +
                         std::string("the checkpoint '") + previous +
                         "' is unusable: " + error.what();
            }
        if (found.empty() && !damaged.empty())
          problem = "option --resume: " + damaged +
                    (fs::exists(previous) ? ""
                                          : "; there is no earlier checkpoint "
                                            "('" +
                                              previous + "/') to fall back to");
        else if (found.empty())
          problem = "option --resume: no checkpoint in '" + output_directory +
                    "' (expected '" + current +
                    "/'; it is written at the steps set by 'Checkpoint/"
                    "Interval steps' and 'Interval minutes', and on SIGTERM "
                    "or SIGINT)";
        if (!warning.empty())
          std::cerr << "vefs: warning: option --resume: " << warning
                    << std::endl;
      }
    problem = Utilities::MPI::broadcast(comm, problem, 0);
    if (!problem.empty())
      throw InputError(problem);
    return Utilities::MPI::broadcast(comm, found, 0);
  }

  template <int dim>
  std::string
  write_checkpoint(const std::string            &output_directory,
                   const std::string            &parameters_text,
                   const TransportedFields<dim> &fields,
                   const LevelSetGradient<dim>  &level_set_gradient,
                   const LevelSetHistory<dim>   &history,
                   const RunState<dim>          &state)
  {
    const auto &triangulation =
      dynamic_cast<const parallel::distributed::Triangulation<dim> &>(
        fields.dof_handler.get_triangulation());
    const MPI_Comm    comm = triangulation.get_communicator();
    const bool        root = Utilities::MPI::this_mpi_process(comm) == 0;
    const std::string next = output_directory + "/" + CheckpointNames::next;
    std::string       problem;
    if (root)
      {
        std::error_code error;
        fs::remove_all(next, error);
        if (!error)
          fs::create_directories(next, error);
        if (error)
          problem = "cannot create '" + next + "': " + error.message();
      }
    problem = Utilities::MPI::broadcast(comm, problem, 0);
    if (!problem.empty())
      return problem;
    // A failed write leaves no partial checkpoint (doc/checkpoints.md,
    // "Full disks").
    const auto failed = [&](const std::string &what) {
      if (root)
        {
          std::error_code ignored;
          fs::remove_all(next, ignored);
        }
      return what;
    };

    // The level set gradient as well: the gradient augmented transport
    // carries it (format 1 did not save it, and resumed such runs
    // differently). And the steps since the last remap of the level set.
    std::vector<const typename TransportedFields<dim>::VectorType *> vectors{
      &fields.vector(),
      &level_set_gradient.vector()};
    for (const auto *vector : history.vectors())
      vectors.push_back(vector);

    // Room for it first: p4est's save aborts the process if a write fails.
    // SolutionTransfer writes every dof of every cell of each vector.
    const double needed =
      1.1 * static_cast<double>(triangulation.n_global_active_cells()) *
      (vectors.size() * fields.fe.n_dofs_per_cell() * sizeof(double) + 64);
    if (root)
      {
        const double free = static_cast<double>(free_bytes(output_directory));
        if (free < needed)
          {
            std::ostringstream text;
            text << "cannot write '" << next
                 << "': no space left on the device (about "
                 << std::setprecision(3) << needed / 1e6 << " MB needed, "
                 << free / 1e6 << " MB free)";
            problem = text.str();
          }
      }
    problem = Utilities::MPI::broadcast(comm, problem, 0);
    if (!problem.empty())
      return failed(problem);

    try
      {
        std::ostringstream message;
        message << "the checkpoint of step " << state.statistics.step
                << " (t = " << state.statistics.time
                << ") was not written: cannot write '" << next
                << "/mesh': p4est stopped (is the disk full?); the "
                   "statistics end with step "
                << state.statistics.step;
        if (fs::exists(output_directory + "/" + CheckpointNames::current))
          message << ", the last checkpoint is in " << output_directory << "/"
                  << CheckpointNames::current << "/";
        const AbortGuard guard(message.str(),
                               {next, lock_file(output_directory)});
        parallel::distributed::
          SolutionTransfer<dim, typename TransportedFields<dim>::VectorType>
            transfer(fields.dof_handler);
        transfer.prepare_for_serialization(vectors);
        errno = 0;
        triangulation.save(next + "/mesh");
      }
    catch (const ExceptionBase &)
      {
        problem = write_failure(next);
      }
    catch (const std::exception &)
      {
        problem = write_failure(next);
      }
    // Open MPI's MPI-IO (OMPIO) reports a failed write on the terminal but
    // not to deal.II: a disk left without a byte may hold a truncated file.
    if (root && problem.empty() && free_bytes(output_directory) == 0)
      problem = "cannot write '" + next + "': " + write_failure_cause(ENOSPC);
    for (const std::string &text : Utilities::MPI::all_gather(comm, problem))
      if (!text.empty())
        return failed(text);
    // The files of every rank are complete before rank 0 lists them.
    MPI_Barrier(comm);

    if (root)
      try
        {
          {
            const std::string written =
              checked_write(next + "/parameters.prm",
                            [&](std::ostream &out) { out << parameters_text; });
            if (!written.empty())
              throw std::runtime_error(written);
          }
          const auto        &s = state.statistics;
          std::ostringstream text;
          text << magic << '\n'
               << "dimension " << dim << '\n'
               << "components " << fields.n_components << '\n'
               << "ranks " << Utilities::MPI::n_mpi_processes(comm) << '\n'
               << "step " << s.step << '\n'
               << "time " << exact(s.time) << '\n'
               << "tau " << exact(s.tau) << '\n'
               << "cfl " << exact(s.cfl) << '\n'
               << "max_velocity " << exact(s.max_velocity) << '\n'
               << "max_velocity_gradient " << exact(s.max_velocity_gradient)
               << '\n'
               << "linear_iterations " << s.linear_iterations << '\n'
               << "contact_reaction " << exact(s.contact_reaction) << '\n'
               << "wall_time " << exact(s.wall_time) << '\n'
               << "initial_volume " << exact(state.initial_volume) << '\n'
               << "expected_volume " << exact(state.expected_volume) << '\n'
               << "last_output_step "
               << (state.last_output_step == numbers::invalid_unsigned_int
                     ? std::string("none")
                     : std::to_string(state.last_output_step))
               << '\n';
          for (const auto &[time, name] : state.visualization_series)
            text << "output " << exact(time) << ' ' << name << '\n';
          text << "contact_state";
          for (const Point<dim> &node : state.contact_state)
            for (unsigned int d = 0; d < dim; ++d)
              text << ' ' << exact(node[d]);
          text << '\n';
          if (!fields.dumbbell_controls.empty())
            {
              text << "dumbbell_controls";
              for (const auto &p : fields.dumbbell_controls)
                for (unsigned int d = 0; d < dim; ++d)
                  text << ' ' << exact(p[d]);
              text << '\n';
            }
          const auto remap = history.scalars();
          text << "level_set_history " << remap.has_base << ' '
               << exact(remap.moved);
          for (const double tau : remap.taus)
            text << ' ' << exact(tau);
          text << '\n';
          text << file_lines(next) << "end\n";
          {
            const std::string written =
              checked_write(next + "/state", [&](std::ostream &out) {
                out << sealed(text.str());
              });
            if (!written.empty())
              throw std::runtime_error(written);
          }
          // Two renames: between them checkpoint.old is the complete one.
          // The one before stays as checkpoint.old: --resume falls back to
          // it if the newest is damaged. Without a checkpoint/ (a kill
          // between the renames, or the damaged one set aside on resume)
          // checkpoint.old is the last good one and is kept.
          const std::string current =
            output_directory + "/" + CheckpointNames::current;
          const std::string previous =
            output_directory + "/" + CheckpointNames::previous;
          if (fs::exists(current))
            {
              fs::remove_all(previous);
              fs::rename(current, previous);
            }
          fs::rename(next, current);
        }
      catch (const std::exception &error)
        {
          problem = error.what();
        }
    problem = Utilities::MPI::broadcast(comm, problem, 0);
    return problem.empty() ? problem : failed(problem);
  }

  template <int dim>
  RunState<dim>
  read_checkpoint(const std::string                         &directory,
                  parallel::distributed::Triangulation<dim> &triangulation,
                  TransportedFields<dim>                    &fields,
                  LevelSetGradient<dim>                     &level_set_gradient,
                  LevelSetHistory<dim>                      &history)
  {
    const MPI_Comm comm = triangulation.get_communicator();
    std::string    problem, text;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      try
        {
          text = read_and_verify(directory);
        }
      catch (const std::exception &error)
        {
          problem = error.what();
        }
    problem = Utilities::MPI::broadcast(comm, problem, 0);
    text    = Utilities::MPI::broadcast(comm, text, 0);

    RunState<dim>                          state;
    typename LevelSetHistory<dim>::Scalars remap;
    try
      {
        if (!problem.empty())
          throw std::runtime_error(problem);
        const Entries entries = parse_entries(text);
        const auto    value   = [&](const std::string &key) {
          return entry(entries, key)[0];
        };
        if (to_unsigned(value("dimension")) != dim ||
            to_unsigned(value("components")) != fields.n_components)
          throw std::runtime_error("it holds other fields than this scene");
        auto &s                 = state.statistics;
        s.step                  = to_unsigned(value("step"));
        s.time                  = to_double(value("time"));
        s.tau                   = to_double(value("tau"));
        s.cfl                   = to_double(value("cfl"));
        s.max_velocity          = to_double(value("max_velocity"));
        s.max_velocity_gradient = to_double(value("max_velocity_gradient"));
        s.linear_iterations     = to_unsigned(value("linear_iterations"));
        // Checkpoints written before the mean contact force have no such
        // line (their runs then restart that mean from zero).
        if (const auto found = entries.find("contact_reaction");
            found != entries.end() && !found->second.empty())
          s.contact_reaction = to_double(found->second[0]);
        // Checkpoints written before it have no contact state (their runs
        // then start the contact set afresh).
        if (const auto found = entries.find("contact_state");
            found != entries.end())
          {
            const auto &values = found->second;
            if (values.size() % dim != 0)
              throw std::runtime_error(
                "its contact_state does not hold whole points");
            for (std::size_t i = 0; i < values.size(); i += dim)
              {
                Point<dim> node;
                for (unsigned int d = 0; d < dim; ++d)
                  node[d] = to_double(values[i + d]);
                state.contact_state.push_back(node);
              }
          }
        // The equilibrium fields of the dumbbells' variance reduction; none
        // without it (and in checkpoints written before it).
        fields.dumbbell_controls.clear();
        if (const auto found = entries.find("dumbbell_controls");
            found != entries.end())
          {
            const auto &values = found->second;
            if (values.size() != dim * fields.n_dumbbell_fields)
              throw std::runtime_error(
                "its dumbbell_controls do not hold one vector per field");
            fields.dumbbell_controls.resize(fields.n_dumbbell_fields);
            for (std::size_t i = 0; i < values.size(); ++i)
              fields.dumbbell_controls[i / dim][i % dim] = to_double(values[i]);
          }
        s.wall_time            = to_double(value("wall_time"));
        state.initial_volume   = to_double(value("initial_volume"));
        state.expected_volume  = to_double(value("expected_volume"));
        state.last_output_step = value("last_output_step") == "none"
                                   ? numbers::invalid_unsigned_int
                                   : to_unsigned(value("last_output_step"));
        // Checkpoints written before the remap distance have no such line.
        if (const auto found = entries.find("level_set_history");
            found != entries.end())
          {
            const auto &values = found->second;
            if (values.size() < 2)
              throw std::runtime_error(
                "'state' has a malformed level_set_history line");
            remap.has_base = to_unsigned(values[0]) != 0;
            remap.moved    = to_double(values[1]);
            for (unsigned int i = 2; i < values.size(); ++i)
              remap.taus.push_back(to_double(values[i]));
          }
        for (auto [it, end] = entries.equal_range("output"); it != end; ++it)
          {
            if (it->second.size() != 2)
              throw std::runtime_error("'state' has a malformed output line");
            state.visualization_series.emplace_back(to_double(it->second[0]),
                                                    it->second[1]);
          }
      }
    catch (const std::exception &error)
      {
        throw CheckpointError("option --resume: the checkpoint '" + directory +
                              "' is unusable: " + error.what());
      }

    // The files passed their checksums: p4est reads a sound forest.
    triangulation.load(directory + "/mesh");
    fields.setup_dofs();
    std::vector<typename TransportedFields<dim>::VectorType>   loaded(2);
    std::vector<typename TransportedFields<dim>::VectorType *> targets;
    for (auto &vector : loaded)
      {
        fields.initialize_vector(vector);
        vector.zero_out_ghost_values();
        targets.push_back(&vector);
      }
    for (auto *vector : history.restore(remap, fields))
      targets.push_back(vector);
    parallel::distributed::
      SolutionTransfer<dim, typename TransportedFields<dim>::VectorType>
        transfer(fields.dof_handler);
    transfer.deserialize(targets);
    fields.mutable_vector() = loaded[0];
    fields.finalize();
    level_set_gradient.reinit(fields);
    level_set_gradient.mutable_vector() = loaded[1];
    level_set_gradient.finalize(fields);
    history.restored();
    // Resumed from checkpoint.old/ because checkpoint/ is damaged: set the
    // damaged one aside, so that the next checkpoint keeps the good one as
    // checkpoint.old/.
    const fs::path from(directory);
    const fs::path damaged = from.parent_path() / CheckpointNames::current;
    if (Utilities::MPI::this_mpi_process(comm) == 0 &&
        from.filename() == CheckpointNames::previous && fs::exists(damaged))
      {
        const fs::path  aside = from.parent_path() / CheckpointNames::damaged;
        std::error_code error;
        fs::remove_all(aside, error);
        fs::rename(damaged, aside, error);
        if (error)
          fs::remove_all(damaged, error);
      }
    return state;
  }

  template std::string
  write_checkpoint<2>(const std::string &,
                      const std::string &,
                      const TransportedFields<2> &,
                      const LevelSetGradient<2> &,
                      const LevelSetHistory<2> &,
                      const RunState<2> &);
  template std::string
  write_checkpoint<3>(const std::string &,
                      const std::string &,
                      const TransportedFields<3> &,
                      const LevelSetGradient<3> &,
                      const LevelSetHistory<3> &,
                      const RunState<3> &);
  template RunState<2>
  read_checkpoint<2>(const std::string &,
                     parallel::distributed::Triangulation<2> &,
                     TransportedFields<2> &,
                     LevelSetGradient<2> &,
                     LevelSetHistory<2> &);
  template RunState<3>
  read_checkpoint<3>(const std::string &,
                     parallel::distributed::Triangulation<3> &,
                     TransportedFields<3> &,
                     LevelSetGradient<3> &,
                     LevelSetHistory<3> &);
} // namespace vefs
