"""Checker of translation_one_change.cmd: the disk translated by whole
finest cells with the mesh changed once per step ('predicted, one change',
directory 1) and twice ('predicted', directory 2). Prints the relative L1
shape error of both against the exact translated disk, whether the first
is below 0.01 and at most 1.1 times the second, whether its final volume
change is below 1e-9, and whether the surface stayed in the finest cells
(then no mesh change after the advection was needed)."""
import sys

from vefs_tools.statistics import read_statistics

one, two = (read_statistics(d) for d in sys.argv[1:3])
v0 = one["volume"][0]
error_one = one["shape_error"][-1] / v0
error_two = two["shape_error"][-1] / v0
print("steps: %d" % (len(one["time"]) - 1))
print("relative L1 shape error, one change per step: %.2g" % error_one)
print("relative L1 shape error, two changes per step: %.2g" % error_two)
print("one change: error below 0.01 and at most 1.1 times two changes': %s"
      % ("yes" if error_one < 0.01 and error_one <= 1.1 * error_two
         else "NO"))
print("final |volume change| below 1e-9: %s"
      % ("yes" if abs(one["volume_change"][-1]) < 1e-9 else "NO"))
print("surface in the finest cells after every advection: %s"
      % ("yes" if max(one["coarse_surface_cells"][1:]) == 0 else "NO"))
