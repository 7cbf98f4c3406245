#include <deal.II/base/numbers.h>

#include <vefs/base/errors.h>
#include <vefs/core/resource_limits.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <limits>
#include <numeric>
#include <sstream>

namespace vefs
{
  namespace
  {
    /** MemAvailable of /proc/meminfo in bytes; 0 if unknown. */
    double
    available_memory()
    {
      std::ifstream meminfo("/proc/meminfo");
      std::string   key;
      double        kilobytes;
      std::string   unit;
      while (meminfo >> key >> kilobytes >> unit)
        if (key == "MemAvailable:")
          return 1024 * kilobytes;
      return 0;
    }

    std::string
    rounded(const double value)
    {
      std::ostringstream text;
      text.precision(2);
      text << value;
      return text.str();
    }

    /**
     * Volume (area in 2D) of the initial liquid, infinite where it is not
     * bounded: an expression shape, or a velocity wall that may let liquid in.
     */
    double
    initial_liquid_volume(const Parameters &p)
    {
      const unsigned int dim       = p.dimension;
      const double       unbounded = std::numeric_limits<double>::infinity();
      if (std::find(p.cavity.wall_type.begin(),
                    p.cavity.wall_type.end(),
                    WallType::velocity) != p.cavity.wall_type.end())
        return unbounded;
      if (p.initial_liquid.initial_shape == "ball")
        return (dim == 2 ? dealii::numbers::PI : 4. / 3 * dealii::numbers::PI) *
               std::pow(p.initial_liquid.ball_radius, static_cast<int>(dim));
      if (p.initial_liquid.initial_shape == "box")
        {
          double volume = 1;
          for (unsigned int d = 0; d < dim; ++d)
            volume *= std::max(0.,
                               p.initial_liquid.box_upper[d] -
                                 p.initial_liquid.box_lower[d]);
          return volume;
        }
      return unbounded;
    }
  } // namespace

  double
  estimated_cells(const Parameters &p)
  {
    const unsigned int  dim          = p.dimension;
    double              coarse_cells = 1, smallest_coarse_size = 1e300;
    std::vector<double> extent(dim);
    for (unsigned int d = 0; d < dim; ++d)
      {
        extent[d] = p.cavity.cavity_upper[d] - p.cavity.cavity_lower[d];
        coarse_cells *= p.cavity.coarse_subdivisions[d];
        smallest_coarse_size =
          std::min(smallest_coarse_size,
                   extent[d] / p.cavity.coarse_subdivisions[d]);
      }
    // The cavity at the minimum level, and the liquid at the bulk level:
    // its volume is kept, unless a velocity wall lets liquid in or the
    // initial shape is an expression (then it may fill the cavity).
    const double cavity_volume =
      std::accumulate(extent.begin(), extent.end(), 1., std::multiplies<>());
    const double liquid_fraction =
      std::min(1., initial_liquid_volume(p) / cavity_volume);
    const double bulk =
      coarse_cells * (std::pow(2., dim * p.mesh.min_level) +
                      liquid_fraction * std::pow(2., dim * p.mesh.bulk_level));
    // ... and its surface, at most about the largest cross-section of the
    // cavity, carries a band of finest cells as wide as the band width
    // (or CFL + 2) on either side, twice that with the grading around it.
    // Refined ahead of the surface, the band keeps its width and the rest
    // of the CFL + 2 cells is one level coarser (2^dim times fewer cells).
    std::sort(extent.begin(), extent.end());
    double cross_section = 1;
    for (unsigned int d = 1; d < dim; ++d)
      cross_section *= extent[d];
    const double h     = smallest_coarse_size / std::pow(2., p.mesh.max_level);
    const double reach = std::max(p.mesh.band_width, p.time.target_cfl + 2);
    const double width = p.mesh.band_predicted()
                           ? p.mesh.band_width + reach / std::pow(2., dim)
                           : reach;
    const double band =
      2 * 2 * width * cross_section / std::pow(h, static_cast<int>(dim) - 1);
    return bulk + band;
  }

  double
  bytes_per_cell(const unsigned int dimension,
                 const unsigned int flow_level_offset)
  {
    // doc/reliability.md, "Limits": 2D 3.6 kB per cell measured; 3D with
    // the flow on coarser cells 10-11 kB (the 2.5 mm ball), a factor 2 for
    // both; 3D on the finest cells an estimate.
    if (dimension == 2)
      return 8e3;
    return flow_level_offset > 0 ? 20e3 : 40e3;
  }

  void
  check_resources(const Parameters &p)
  {
    const double steps =
      std::ceil(p.time.end_time / p.time.time_step * (1 - 1e-12));
    if (steps > p.time.maximum_steps)
      throw InputError(
        "entry 'Time/Time step': 'Time/End time' / 'Time/Time step' = " +
        rounded(steps) + " steps, more than 'Time/Maximum steps' = " +
        std::to_string(p.time.maximum_steps) +
        "; raise the time step (with 'Time/Target CFL' it is the largest "
        "step allowed) or 'Time/Maximum steps'");

    const double cells = estimated_cells(p);
    const double needed =
      cells * bytes_per_cell(p.dimension, p.flow.flow_level_offset);
    const double memory = available_memory();
    if (memory > 0 && needed > memory)
      throw InputError(
        "entry 'Mesh refinement/Maximum level': the levels (bulk " +
        std::to_string(p.mesh.bulk_level) + ", maximum " +
        std::to_string(p.mesh.max_level) + ") may need about " +
        rounded(cells) + " cells and " + rounded(needed / 1e9) +
        " GB of memory, more than the " + rounded(memory / 1e9) +
        " GB available (MemAvailable in /proc/meminfo); lower "
        "'Mesh refinement/Maximum level' or 'Mesh refinement/Bulk level'");
  }
} // namespace vefs
