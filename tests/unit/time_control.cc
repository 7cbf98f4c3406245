// TimeControl (time_control.h, doc/time_step_surface.md step 1): the step
// lengths it chooses, against the values its rules give in closed form
// (finest cells h = 0.01, 'Time step' 0.01 unless said, tolerance 1e-14 of
// the step).
// - Flow: 'Time step' when nothing is faster; CFL h / |u|max; the strain
//   bound s / |grad u|max; from rest under gravity sqrt(CFL h / |g|), the
//   step after which gravity alone has moved the liquid CFL cells.
// - Prescribed velocity of constant speed: CFL h / speed; of a speed that
//   grows within the step: the CFL number holds at the start, middle and
//   end of the step.
// - Landing: a step that overshoots the end time or the next output time
//   ends on it; a remainder below 5/4 of the step is split into two halves
//   (no sliver step).

#include "unit_test.h"

#include <vefs/base/time_control.h>

#include <array>
#include <cmath>
#include <iostream>
#include <tuple>

namespace
{
  const double h = 0.01;

  vefs::TimeControl
  clock(const double time_step,
        const double target_cfl,
        const double max_strain,
        const double output_time_interval = 0)
  {
    vefs::TimeParameters time;
    time.end_time            = 1;
    time.time_step           = time_step;
    time.target_cfl          = target_cfl;
    time.max_strain_per_step = max_strain;
    vefs::OutputParameters output;
    output.output_time_interval = output_time_interval;
    return vefs::TimeControl(time, output, {0, -9.81}, h);
  }

  void
  check_step(std::ostream      &out,
             const std::string &label,
             const double       tau,
             const double       expected)
  {
    unit_test::check_below(out,
                           label + ", relative error",
                           std::abs(tau - expected) / expected,
                           1e-14);
  }
} // namespace

int
main(int argc, char **argv)
{
  return unit_test::run(argc, argv, [](std::ostream &out) {
    // Flow steps.
    check_step(out,
               "flow, slow",
               clock(0.01, 2, 0).flow_time_step(1, 0).tau,
               0.01);
    check_step(out,
               "flow, CFL 2 at 4 m/s",
               clock(0.01, 2, 0).flow_time_step(4, 0).tau,
               2 * h / 4);
    check_step(out,
               "flow, strain 0.25 at |grad u| 200",
               clock(0.01, 2, 0.25).flow_time_step(1, 200).tau,
               0.25 / 200);
    check_step(out,
               "flow, from rest under gravity",
               clock(1, 2, 0).flow_time_step(0, 0).tau,
               std::sqrt(2 * h / 9.81));

    // Prescribed velocities.
    vefs::TimeControl prescribed = clock(1, 5, 0);
    check_step(out,
               "prescribed, constant speed 2",
               prescribed.prescribed_time_step([](double) { return 2.; }).tau,
               5 * h / 2);
    const auto   growing = [](const double t) { return 1 + 10 * t; };
    const double tau     = prescribed.prescribed_time_step(growing).tau;
    const double largest_cfl =
      std::max({growing(0), growing(tau / 2), growing(tau)}) * tau / h;
    out << "prescribed, speed 1 + 10 t: CFL at the start, middle and end at "
           "most 5: "
        << (largest_cfl <= 5 * (1 + 1e-12) ? "yes" : "NO") << '\n';

    // Landing on the end time (1) and on output times.
    // (time at the start, step expected) for steps of 0.1 to the end time 1.
    const std::array<std::tuple<const char *, double, double>, 4> landings = {
      {{"landing, 0.1 left of 1", 0.9, 0.1},
       {"landing, 0.15 left: a full step", 0.85, 0.1},
       {"landing, 0.12 left: two halves", 0.88, 0.06},
       {"landing, 0.05 left: shortened", 0.95, 0.05}}};
    vefs::TimeControl landing = clock(0.1, 0, 0);
    for (const auto &[label, time, expected] : landings)
      {
        landing.resume(8, time, 0.1);
        check_step(out, label, landing.landed({0.1, 0.1}).tau, expected);
      }
    vefs::TimeControl output = clock(0.1, 0, 0, 0.3);
    output.resume(2, 0.25, 0.1);
    check_step(out,
               "landing on the output time 0.3",
               output.landed({0.1, 0.1}).tau,
               0.05);
  });
}
