"""Rider-Kothe vortex at finest cells 1/64, correction off: CFL 5 (the level
set interpolated every step) against CFL 1 with 'Remap distance' = 10.
Prints the L1 area error int |phi - phi_exact| (reference: the initial
disk, the exact final shape) and the raw volume change of both runs, two
significant digits; ok if CFL 1 is no worse than CFL 5 in both."""
import sys

from vefs_tools.statistics import read_statistics

results = {}
for label, directory in (("CFL 5, every step", sys.argv[1]),
                         ("CFL 1, remap distance 10", sys.argv[2])):
    s = read_statistics(directory)
    results[label] = (s["shape_error"][-1], s["volume_change"][-1])
    print("%s: final time %.4g, L1 shape error %.2g, raw volume change %.2g"
          % (label, s["time"][-1], results[label][0], results[label][1]))
every_step, remapped = results.values()
ok = remapped[0] <= every_step[0] and abs(remapped[1]) <= abs(every_step[1])
print("CFL 1 no worse than CFL 5 (L1 error and |volume change|): %s"
      % ("ok" if ok else "FAIL"))
