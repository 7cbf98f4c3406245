#ifndef vefs_parameter_file_h
#define vefs_parameter_file_h

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace vefs
{
  /**
   * An entry that moved from one top-level subsection to another: a file
   * that sets it at its old place is still read, with a warning.
   */
  struct MovedEntry
  {
    std::string old_subsection;
    std::string new_subsection;
    std::string name;
  };

  /**
   * Reads @p file into @p prm, which holds every entry declared, and
   * returns the warnings for the user. Refuses (InputError) what deal.II's
   * ParameterHandler accepts silently but is almost always a mistake: a
   * directory given as the file, a file without any 'set' line, an entry
   * set twice (the last one would win). An entry of @p moved_entries set at
   * its old place is read into its new one, with a warning naming it.
   */
  std::vector<std::string>
  read_parameter_file(dealii::ParameterHandler      &prm,
                      const std::string             &file,
                      const std::vector<MovedEntry> &moved_entries);
} // namespace vefs

#endif
