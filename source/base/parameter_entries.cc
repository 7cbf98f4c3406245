#include <vefs/base/parameter_entries.h>

namespace vefs
{
  void
  require_point(const std::vector<double> &point,
                const unsigned int         dimension,
                const std::string         &entry)
  {
    const std::string dim_text = std::to_string(dimension);
    require(point.size() == dimension,
            entry,
            "needs " + dim_text + " comma-separated numbers (Dimension = " +
              dim_text + "), got " + std::to_string(point.size()));
  }
} // namespace vefs
