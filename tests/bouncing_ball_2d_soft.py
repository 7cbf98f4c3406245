"""Checker of bouncing_ball_2d_soft: the seed's soft ball (G = 20 Pa) hits a
contact floor at about 1 m/s, rho v^2 / G = 50, and spreads.

References, exact for the continuous problem:
 - B = F F^T is positive definite: its smallest eigenvalue at the
   quadrature points of the liquid stays positive at every step.
 - The volume is kept (bound 1e-6; the global correction is on).
 - No energy source acts after the fall: the total energy (kinetic,
   potential, elastic) at the end is below its value at the first contact
   (the impact and the first-order scheme only remove energy).
 - The body stays on the floor: the centroid stays above 0 and below its
   initial height.
Printed with 2 significant digits: first contact time, lowest centroid
height and its time, largest contact force until then, the energy lost."""
import sys

from vefs_tools.statistics import read_statistics

s = read_statistics(sys.argv[1])
t, y, F = s["time"], s["centroid_y"], s["contact_force"]
n = len(t)
energy = [k + p + e for k, p, e in
          zip(s["kinetic_energy"], s["potential_energy"], s["elastic_energy"])]

first = next(i for i in range(n) if F[i] > 0)
print("first contact at t = %.2g s" % t[first])
lowest = min(range(n), key=lambda i: y[i])
print("lowest centroid height %.2g m at t = %.2g s (initial 0.15)" % (y[lowest], t[lowest]))
# Up to the lowest centroid: the test ends as a second impact begins,
# whose first steps give a spike that is not a property of the first one.
print("largest contact force until the lowest centroid: %.2g N/m"
      % max(F[:lowest + 1]))
print("B positive definite at every step: %s"
      % ("yes" if min(s["min_conformation_eigenvalue"]) > 0 else "NO"))
print("max |volume change| below 1e-6: %s"
      % ("yes" if max(abs(v) for v in s["volume_change"]) < 1e-6 else "NO"))
print("centroid between the floor and its initial height: %s"
      % ("yes" if all(0 < v <= y[0] for v in y) else "NO"))
lost = energy[first] - energy[-1]
print("energy lost from the first contact to the end: %.2g J/m (%s)"
      % (lost, "a loss" if lost > 0 else "NO, a gain"))
