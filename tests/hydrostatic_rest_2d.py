"""Hydrostatic rest (exact solution u = 0): the largest speed over the run
must stay at round-off, and the liquid volume must not change.
Tolerances: speed below 1e-8 m/s (the solver tolerance is 1e-13) (gravity 9.81 m/s^2 over 0.1 s would give
~1 m/s if the pressure did not balance it), relative volume change below
1e-9; the exact initial volume is 0.2 * 0.0503 = 0.01006 m^2."""
import sys

from vefs_tools.statistics import read_statistics

s = read_statistics(sys.argv[1])
print("steps run: %d" % (len(s["step"]) - 1))
print("initial volume: %.4g (exact 0.01006)" % s["volume"][0])
print("max speed below 1e-8: %s" % ("yes" if max(s["max_velocity"]) < 1e-8 else "NO"))
print("max |volume change| below 1e-9: %s"
      % ("yes" if max(abs(v) for v in s["volume_change"]) < 1e-9 else "NO"))
print("final centroid height: %.4g (exact 0.02515)" % s["centroid_y"][-1])
