#ifndef vefs_parameter_entries_h
#define vefs_parameter_entries_h

#include <deal.II/base/parameter_handler.h>

#include <vefs/base/errors.h>

#include <string>
#include <utility>
#include <vector>

namespace vefs
{
  /** "entry 'ENTRY': WHAT", the form of every message about an entry. */
  inline std::string
  entry_message(const std::string &entry, const std::string &what)
  {
    return "entry '" + entry + "': " + what;
  }

  /** Throws InputError with entry_message(entry, what) unless @p condition. */
  inline void
  require(const bool         condition,
          const std::string &entry,
          const std::string &what)
  {
    if (!condition)
      throw InputError(entry_message(entry, what));
  }

  /** Requires @p point to have @p dimension coordinates. */
  void
  require_point(const std::vector<double> &point,
                const unsigned int         dimension,
                const std::string         &entry);

  /**
   * Declares the entry @p entry whose allowed values are the names of
   * @p choices (in that order), bound to @p value: its default is the name
   * of the present @p value, and each name read stores its choice there.
   */
  template <typename T>
  void
  add_selection(dealii::ParameterHandler                     &prm,
                const std::string                            &entry,
                T                                            &value,
                const std::vector<std::pair<std::string, T>> &choices,
                const std::string                            &documentation)
  {
    std::string names, current;
    for (const auto &[name, choice] : choices)
      {
        names += (names.empty() ? "" : "|") + name;
        if (choice == value && current.empty())
          current = name;
      }
    prm.declare_entry(entry,
                      current,
                      dealii::Patterns::Selection(names),
                      documentation);
    prm.add_action(entry, [&value, choices](const std::string &text) {
      for (const auto &[name, choice] : choices)
        if (name == text)
          value = choice;
    });
  }

  /**
   * Declares the entry @p entry (of the subsection @p path, for messages)
   * whose value is 'automatic' (its default: @p automatic becomes true) or
   * a number of at least @p minimum, stored in @p value (@p automatic
   * becomes false). Anything else throws InputError naming the entry.
   */
  void
  add_number_or_automatic(dealii::ParameterHandler &prm,
                          const std::string        &path,
                          const std::string        &entry,
                          double                   &value,
                          bool                     &automatic,
                          const double              minimum,
                          const std::string        &documentation);
} // namespace vefs

#endif
