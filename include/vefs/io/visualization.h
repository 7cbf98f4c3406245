#ifndef vefs_visualization_h
#define vefs_visualization_h

#include <vefs/fields/transported_fields.h>
#include <vefs/flow/stokes_step.h>

#include <string>
#include <utility>
#include <vector>

namespace vefs
{
  /**
   * Writes the `.pvtu` files of a run and keeps its `.pvd` time series up to
   * date, so that ParaView can open the series while the run goes on.
   */
  template <int dim>
  class Visualization
  {
  public:
    explicit Visualization(const std::string &directory);

    /**
     * Write the state after @p step (at @p time); collective. A write that
     * fails (a full disk) throws OutputError on every rank.
     */
    void
    write(const TransportedFields<dim> &fields,
          const StokesStep<dim>        &flow,
          const Vector<float>          &liquid_fraction,
          const unsigned int            step,
          const double                  time);

    /** The .pvtu file written last, relative to the directory; or "". */
    std::string
    last_file() const
    {
      return series.empty() ? "" : series.back().second;
    }

    /** The (time, .pvtu file) series of solution.pvd. */
    const std::vector<std::pair<double, std::string>> &
    get_series() const
    {
      return series;
    }

    /** Continue the series of a resumed run: the next file follows it. */
    void
    resume(const std::vector<std::pair<double, std::string>> &old_series)
    {
      series = old_series;
    }

  private:
    const std::string                           directory;
    std::vector<std::pair<double, std::string>> series;
  };
} // namespace vefs

#endif
