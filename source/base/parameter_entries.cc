#include <deal.II/base/utilities.h>

#include <vefs/base/parameter_entries.h>

#include <cmath>
#include <sstream>

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

  void
  add_number_or_automatic(dealii::ParameterHandler &prm,
                          const std::string        &path,
                          const std::string        &entry,
                          double                   &value,
                          bool                     &automatic,
                          const double              minimum,
                          const std::string        &documentation)
  {
    prm.declare_entry(entry,
                      "automatic",
                      dealii::Patterns::Anything(),
                      documentation);
    prm.add_action(
      entry,
      [&value, &automatic, path, entry, minimum](const std::string &text) {
        automatic = text == "automatic";
        if (automatic)
          return;
        std::istringstream stream(text);
        double             number;
        char               rest;
        const bool         is_number = (stream >> number) && !(stream >> rest);
        require(is_number && std::isfinite(number) && number >= minimum,
                path + "/" + entry,
                "must be 'automatic' or a number of at least " +
                  dealii::Utilities::to_string(minimum) + ", got '" + text +
                  "'");
        value = number;
      });
  }
} // namespace vefs
