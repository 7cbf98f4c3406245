// EnergyWatch (core/health_check.h) on made-up step statistics, against the
// rule it implements: a step whose total energy (kinetic + potential +
// elastic) grows by more than 'Health check/Maximum energy growth' of the
// energy above the lowest state is reported, if the watch is active and the
// step's elastic wave number lies beyond the trusted 10; the first step is
// never judged. Cavity [0, 1] x [0, 2], gravity (0, -10), density 1000:
// the lowest state has all the liquid at y = 0, so the energy above it is
// the total energy itself; with the floor at y = -1 it is 100 more.

#include "unit_test.h"

#include <vefs/core/health_check.h>

#include <iostream>

namespace
{
  vefs::StepStatistics<2>
  step(const double kinetic, const double wave_number)
  {
    vefs::StepStatistics<2> s;
    s.kinetic_energy      = kinetic;
    s.potential_energy    = 100;
    s.elastic_energy      = 0;
    s.volume              = 0.01;
    s.elastic_wave_number = wave_number;
    return s;
  }

  /** "reported" or "not reported" for the second of two steps. */
  std::string
  judged(const bool   active,
         const double second_kinetic,
         const double wave_number,
         const double floor = 0)
  {
    vefs::MaterialParameters material;
    material.gravity = {0, -10};
    vefs::CavityParameters cavity;
    cavity.cavity_lower = {0, floor};
    cavity.cavity_upper = {1, 2};
    vefs::HealthCheckParameters bounds;
    bounds.max_energy_growth = 0.01;
    vefs::EnergyWatch watch(active, material, cavity);
    const std::string first =
      watch.problem(bounds, step(100, wave_number)); // total 200
    const std::string second =
      watch.problem(bounds, step(second_kinetic, wave_number));
    return std::string(first.empty() ? "" : "first step judged, ") +
           (second.empty() ? "not reported" : "reported");
  }
} // namespace

int
main()
{
  std::ostream &out = std::cout;
  // The total goes from 200 to 200 + growth: the bound is 2.
  out << "growth 2.1 at wave number 20: " << judged(true, 102.1, 20) << '\n';
  out << "growth 1.9 at wave number 20: " << judged(true, 101.9, 20) << '\n';
  out << "growth 2.1 at wave number 9: " << judged(true, 102.1, 9) << '\n';
  out << "growth 2.1 at wave number 20, not watched: "
      << judged(false, 102.1, 20) << '\n';
  out << "loss 50 at wave number 20: " << judged(true, 50, 20) << '\n';
  // Floor at y = -1: the lowest state lies 10 * 1000 * 0.01 = 100 below
  // the potential's zero, so the energy above it is 300 and the bound 3.
  out << "floor at -1, growth 2.1: " << judged(true, 102.1, 20, -1) << '\n';
  out << "floor at -1, growth 3.1: " << judged(true, 103.1, 20, -1) << '\n';
}
