#include <deal.II/base/utilities.h>

#include <vefs/base/errors.h>
#include <vefs/base/parameter_file.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace vefs
{
  namespace
  {
    /** The line without its comment and surrounding blanks. */
    std::string
    stripped(std::string line)
    {
      const auto comment = line.find('#');
      if (comment != std::string::npos)
        line.erase(comment);
      return dealii::Utilities::trim(line);
    }

    /** Inner blanks of a name collapsed, as ParameterHandler does. */
    std::string
    normalized(const std::string &name)
    {
      std::string result;
      for (const char c : dealii::Utilities::trim(name))
        if (!(std::isspace(c) && !result.empty() && result.back() == ' '))
          result.push_back(std::isspace(c) ? ' ' : c);
      return result;
    }

    bool
    starts_with_word(const std::string &line, const std::string &word)
    {
      return line.size() > word.size() &&
             line.compare(0, word.size(), word) == 0 &&
             std::isspace(line[word.size()]);
    }

    /** A moved entry found at its old place: where it goes, what it says. */
    struct MovedSetting
    {
      const MovedEntry *entry;
      std::string       value;
      unsigned int      line;
    };

    /** The text of a deal.II exception for the user, without its trace. */
    std::string
    message_of(const dealii::ExceptionBase &exception)
    {
      std::ostringstream text;
      exception.print_info(text);
      return dealii::Utilities::trim(text.str());
    }
  } // namespace

  std::vector<std::string>
  read_parameter_file(dealii::ParameterHandler      &prm,
                      const std::string             &file,
                      const std::vector<MovedEntry> &moved_entries)
  {
    if (std::filesystem::is_directory(file))
      throw InputError("this is a directory, not a parameter file");
    std::ifstream input(file);
    if (!input)
      throw InputError("cannot open the parameter file");

    // The text ParameterHandler reads: the file with the lines of moved
    // entries blanked, so that its line numbers stay those of the file.
    std::ostringstream                  text;
    std::vector<MovedSetting>           moved;
    std::vector<std::string>            path;
    std::map<std::string, unsigned int> first_line;
    unsigned int                        number = 0;
    std::string                         line;
    while (std::getline(input, line))
      {
        ++number;
        const unsigned int first = number;
        std::string        whole = line;
        // A trailing backslash continues the value on the next line.
        while (!whole.empty() && whole.back() == '\\' && input)
          {
            std::string next;
            std::getline(input, next);
            ++number;
            line += "\n" + next;
            whole.pop_back();
            whole += next;
          }
        const std::string content = stripped(whole);
        if (starts_with_word(content, "subsection"))
          path.push_back(normalized(content.substr(10)));
        else if (content == "end" && !path.empty())
          path.pop_back();
        else if (starts_with_word(content, "set") &&
                 content.find('=') != std::string::npos)
          {
            const auto        equal = content.find('=');
            const std::string name  = normalized(content.substr(3, equal - 3));
            const MovedEntry *move  = nullptr;
            for (const auto &candidate : moved_entries)
              if (path.size() == 1 && path[0] == candidate.old_subsection &&
                  name == candidate.name)
                move = &candidate;
            std::string entry;
            for (const auto &section :
                 move ? std::vector<std::string>{move->new_subsection} : path)
              entry += section + "/";
            entry += name;
            const auto [known, inserted] = first_line.emplace(entry, first);
            if (!inserted)
              throw InputError("entry '" + entry + "': set twice (lines " +
                               std::to_string(known->second) + " and " +
                               std::to_string(first) +
                               "); the last value would win silently, keep "
                               "one of them");
            if (move)
              {
                moved.push_back(MovedSetting{move,
                                             dealii::Utilities::trim(
                                               content.substr(equal + 1)),
                                             first});
                line = std::string(number - first, '\n');
              }
          }
        text << line << '\n';
      }
    if (first_line.empty())
      throw InputError("the file sets no entry (it is empty or has only "
                       "comments); add 'set' lines, or run vefs without a "
                       "file for the default scene");

    std::istringstream parsed(text.str());
    prm.parse_input(parsed, file);

    std::vector<std::string> warnings;
    for (const auto &setting : moved)
      {
        const std::string old_path =
          setting.entry->old_subsection + "/" + setting.entry->name;
        const std::string new_path =
          setting.entry->new_subsection + "/" + setting.entry->name;
        prm.enter_subsection(setting.entry->new_subsection);
        try
          {
            prm.set(setting.entry->name, setting.value);
          }
        catch (const dealii::ExceptionBase &error)
          {
            throw InputError("entry '" + new_path + "' (line " +
                             std::to_string(setting.line) + ", as '" +
                             old_path + "'): " + message_of(error));
          }
        prm.leave_subsection();
        warnings.push_back("entry '" + old_path + "' (line " +
                           std::to_string(setting.line) + ") has moved to '" +
                           new_path +
                           "'; it is read there, but write it "
                           "there: the old place will be refused in a later "
                           "version");
      }
    return warnings;
  }
} // namespace vefs
