#include <deal.II/base/utilities.h>

#include <vefs/base/parameter_file.h>
#include <vefs/base/parameters.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <vector>

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
  } // namespace

  void
  check_parameter_file(const std::string &file)
  {
    if (std::filesystem::is_directory(file))
      throw InputError("this is a directory, not a parameter file");
    std::ifstream input(file);
    if (!input)
      throw InputError("cannot open the parameter file");

    std::vector<std::string>            path;
    std::map<std::string, unsigned int> first_line;
    unsigned int                        number = 0;
    std::string                         line;
    while (std::getline(input, line))
      {
        ++number;
        // A trailing backslash continues the value on the next line.
        while (!line.empty() && line.back() == '\\' && input)
          {
            std::string next;
            std::getline(input, next);
            ++number;
            line.pop_back();
            line += next;
          }
        const std::string text = stripped(line);
        if (starts_with_word(text, "subsection"))
          path.push_back(normalized(text.substr(10)));
        else if (text == "end" && !path.empty())
          path.pop_back();
        else if (starts_with_word(text, "set"))
          {
            const auto equal = text.find('=');
            if (equal == std::string::npos)
              continue; // ParameterHandler reports the malformed line
            std::string entry;
            for (const auto &section : path)
              entry += section + "/";
            entry += normalized(text.substr(3, equal - 3));
            const auto [known, inserted] = first_line.emplace(entry, number);
            if (!inserted)
              throw InputError("entry '" + entry + "': set twice (lines " +
                               std::to_string(known->second) + " and " +
                               std::to_string(number) +
                               "); the last value would win silently, keep "
                               "one of them");
          }
      }
    if (first_line.empty())
      throw InputError("the file sets no entry (it is empty or has only "
                       "comments); add 'set' lines, or run vefs without a "
                       "file for the default scene");
  }
} // namespace vefs
