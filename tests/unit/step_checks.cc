// step_problem() (core/health_check.h) on made-up steps, against the rule
// it implements: 'Health check/Maximum CFL' bounds the CFL number on the
// velocity's cells, 2^k times the finest cells' size with 'Flow/Flow
// cells' at level offset k; a non-finite speed is always reported. The
// bound is 50 (the default), the step 0.01 s of the scene's 0.01 s.

#include "unit_test.h"

#include <vefs/core/health_check.h>

#include <iostream>
#include <limits>

namespace
{
  /** "reported" or "not reported" for a step of CFL @p cfl on the finest
   * cells with flow cells at @p offset. */
  std::string
  judged(const double cfl, const double speed, const unsigned int offset)
  {
    const vefs::HealthCheckParameters health;
    vefs::TimeParameters              time;
    time.time_step = 0.01;
    const std::string problem =
      vefs::step_problem(health, time, 1, 0.01, 0.01, cfl, speed, offset);
    return problem.empty() ? "not reported" : "reported";
  }
} // namespace

int
main()
{
  std::ostream &out = std::cout;
  out << "finest flow cells, CFL 49: " << judged(49, 1, 0) << '\n';
  out << "finest flow cells, CFL 51: " << judged(51, 1, 0) << '\n';
  out << "parents, CFL 99 on the finest cells: " << judged(99, 1, 1) << '\n';
  out << "parents, CFL 101 on the finest cells: " << judged(101, 1, 1) << '\n';
  out << "grandparents, CFL 199 on the finest cells: " << judged(199, 1, 2)
      << '\n';
  out << "grandparents, CFL 201 on the finest cells: " << judged(201, 1, 2)
      << '\n';
  out << "grandparents, infinite speed: "
      << judged(std::numeric_limits<double>::infinity(),
                std::numeric_limits<double>::infinity(),
                2)
      << '\n';
  return 0;
}
