"""Checker of free_fall_second_order: a ball released at 0.1 m/s downward
from y = 0.15 m falls freely; the exact centroid is the parabola
y(t) = 0.15 - 0.1 t - g t^2 / 2 and the total energy (kinetic + potential
+ elastic) stays at its start. Bounds: the centroid within 0.5 mm of the
parabola at every step (issue 49), the energy sum within 0.1 % of its
start."""
import sys

from vefs_tools.statistics import read_statistics

g, y0, v0 = 9.81, 0.15, -0.1

s = read_statistics(sys.argv[1])
t, y, total = s["time"], s["centroid_y"], s["total_energy"]
miss = max(abs(yi - (y0 + v0 * ti - 0.5 * g * ti**2)) for ti, yi in zip(t, y))
drift = max(abs(e / total[0] - 1) for e in total)
print("final time: %.4g" % t[-1])
print("centroid at the end: %.4f m (parabola: %.4f m)"
      % (y[-1], y0 + v0 * t[-1] - 0.5 * g * t[-1] ** 2))
print("centroid within 0.5 mm of the parabola at every step: %s"
      % ("yes" if miss <= 5e-4 else "NO (%.2g m)" % miss))
print("energy sum within 0.1 %% of its start: %s"
      % ("yes" if drift <= 1e-3 else "NO (%.2g)" % drift))
sys.exit(0 if miss <= 5e-4 and drift <= 1e-3 else 1)
