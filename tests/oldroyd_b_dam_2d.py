"""Checker of oldroyd_b_dam_2d.cmd: the broken dam of an Oldroyd-B liquid
(lambda = 0.05 s) against the Newtonian liquid of the same total viscosity,
and the small-relaxation-time limit (lambda = 1e-4 s) against the same
Newtonian liquid, which is its exact limit lambda -> 0 (seed, section 3).
Printed with 3 significant digits: the front on the floor at t = 0.1 and
0.2 s for the three liquids, the relative difference of the small-lambda
front to the Newtonian one (bound 1%), the volume change (bound 1e-6 with
the volume correction), the elastic energy at 0.2 s and the smallest
eigenvalue of the conformation tensor over the run (positive definite:
yes/NO)."""
import sys

from vefs_tools.statistics import read_statistics, interpolate

oldroyd, newtonian, small_lambda = (read_statistics(d) for d in sys.argv[1:4])


def front(s, t):
    return interpolate(s["time"], s["floor_extent"], t)


for t in (0.1, 0.2):
    print("front at t = %.1f s: Newtonian %.3g, Oldroyd-B lambda 0.05 s %.3g, "
          "lambda 1e-4 s %.3g" % (t, front(newtonian, t), front(oldroyd, t),
                                  front(small_lambda, t)))
limit_error = max(abs(front(small_lambda, t) - front(newtonian, t)) / front(newtonian, t)
                  for t in small_lambda["time"] if t > 0)
print("small-lambda front against Newtonian within 1%%: %s"
      % ("yes" if limit_error < 0.01 else "NO (%.3g)" % limit_error))
print("Oldroyd-B front ahead of the Newtonian one at t = 0.2 s: %s"
      % ("yes" if front(oldroyd, 0.2) > front(newtonian, 0.2) else "no"))
volume_change = max(abs(v) for s in (oldroyd, newtonian, small_lambda)
                    for v in s["volume_change"])
print("max |volume change| below 1e-6: %s" % ("yes" if volume_change < 1e-6 else "NO"))
print("elastic energy at t = 0.2 s (J/m): %.3g"
      % interpolate(oldroyd["time"], oldroyd["elastic_energy"], 0.2))
lowest = min(oldroyd["min_conformation_eigenvalue"])
print("smallest conformation eigenvalue: %.3g, positive definite: %s"
      % (lowest, "yes" if lowest > 0 and max(oldroyd["non_positive_conformation_points"]) == 0 else "NO"))
