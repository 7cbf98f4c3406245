"""Checker of rider_kothe_vortex_distance: the largest |volume change| over
all steps (exact answer 0 with the correction; bound 1e-9), every statistic
finite, and the L1 area error int |phi - phi_exact| against the initial disk
below the linear (Q1) transport's at this resolution (6.6e-2 at h = 1/64,
doc/transport.md), printed with three significant digits."""
import math
import sys

from vefs_tools.statistics import read_statistics

s = read_statistics(sys.argv[1])
largest = max(abs(v) for v in s["volume_change"])
finite = all(math.isfinite(v) for name, column in s.items()
             if name != "shape_error" for v in column)
error = s["shape_error"][-1]
print("final time: %.4g" % s["time"][-1])
print("L1 shape error: %.3g" % error)
print("largest |volume change| over the steps below 1e-9: %s"
      % ("yes" if largest < 1e-9 else "NO (%.2g)" % largest))
print("all statistics finite: %s" % ("yes" if finite else "NO"))
ok = largest < 1e-9 and finite and error < 6.6e-2
print("volume kept, finite, L1 below the linear transport's: %s"
      % ("ok" if ok else "FAIL"))
sys.exit(0 if ok else 1)
