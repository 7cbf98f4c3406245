#ifndef vefs_parameter_file_h
#define vefs_parameter_file_h

#include <string>

namespace vefs
{
  /**
   * What deal.II's ParameterHandler accepts silently but is almost always a
   * mistake: a directory given as the file, a file without any 'set' line,
   * an entry set twice (the last one would win). Throws InputError.
   */
  void
  check_parameter_file(const std::string &file);
} // namespace vefs

#endif
