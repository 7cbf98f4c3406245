#ifndef vefs_resource_limits_h
#define vefs_resource_limits_h

#include <vefs/core/parameters.h>

namespace vefs
{
  /** Number of cells the levels of @p parameters may need (an estimate). */
  double
  estimated_cells(const Parameters &parameters);

  /** Bytes of memory a run needs per cell (measured, with a margin), with
   * the flow's cells @p flow_level_offset levels coarser than the finest
   * ('Flow/Flow cells'). */
  double
  bytes_per_cell(const unsigned int dimension,
                 const unsigned int flow_level_offset);

  /**
   * Refuse a scene whose time step and end time imply more steps than
   * 'Time/Maximum steps', or whose levels imply more memory than the
   * machine has available: a run that would never end or end in
   * std::bad_alloc hours later. Throws InputError.
   */
  void
  check_resources(const Parameters &parameters);
} // namespace vefs

#endif
