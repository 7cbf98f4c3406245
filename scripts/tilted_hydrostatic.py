"""Checker of the tests tilted_hydrostatic_2d and tilted_hydrostatic_3d.

Usage: tilted_hydrostatic.py OUTPUT_DIR

Tilted hydrostatic rest (exact solution u = 0, p = rho g . (x - x_s)):
gravity at 30 degrees to the mesh, the free surface perpendicular to it and
cutting the cells obliquely. The largest speed over the run must stay below
1e-6 m/s (issue 9; a staircase of whole cells gave speeds of order g tau,
0.1 m/s, after one step), the volume (exact: half the box, the plane runs
through its centre) must not change by more than 1e-9 relative.
The solver tolerance (1e-12) sets the speeds actually reached."""
import sys

from vefs_tools.statistics import read_statistics
from vefs_tools.prm import read_parameters, parameter_floats

s = read_statistics(sys.argv[1])
prm = read_parameters(sys.argv[1])
lower = parameter_floats(prm, "Cavity/Lower corner")
upper = parameter_floats(prm, "Cavity/Upper corner")
box = 1.0
for a, b in zip(lower, upper):
    box *= b - a
print("steps run: %d" % (len(s["step"]) - 1))
print("initial volume / half the box: %.6f" % (s["volume"][0] / (box / 2)))
print("max speed below 1e-6 m/s: %s"
      % ("yes" if max(s["max_velocity"]) < 1e-6 else "NO"))
print("max |volume change| below 1e-9: %s"
      % ("yes" if max(abs(v) for v in s["volume_change"]) < 1e-9 else "NO"))
