"""Checker of broken_dam_2d_remap: with the volume correction on, the liquid
volume the flow step sees equals the expected one at every step (exact
answer: volume_change = 0, to round-off; bound 1e-9), remap steps with
their mesh changes included. Also prints the final liquid height on the
x- wall and the front, three significant digits."""
import sys

from vefs_tools.statistics import read_statistics

s = read_statistics(sys.argv[1])
largest = max(abs(v) for v in s["volume_change"])
print("final time: %.4g" % s["time"][-1])
print("largest |volume change| over the steps below 1e-9: %s"
      % ("yes" if largest < 1e-9 else "NO (%.2g)" % largest))
print("final wall height: %.3g" % s["wall_height"][-1])
print("final floor extent: %.3g" % s["floor_extent"][-1])
sys.exit(0 if largest < 1e-9 else 1)
