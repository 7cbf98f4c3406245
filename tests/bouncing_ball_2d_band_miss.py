"""Checker of bouncing_ball_2d_band_miss.cmd: the 2D ball with 'Band miss
tolerance = 0.02' (directory 1) against the same with 0 (directory 2).
Prints both runs' lowest centroid and largest contact force and whether
they agree within 1 mm and 5 %, whether the tolerance run kept its volume
to round-off (1e-9) and all liquid above the floor, and whether it changed
the mesh no more often."""
import sys

from vefs_tools.statistics import read_statistics

tolerant, every = (read_statistics(d) for d in sys.argv[1:3])


def yes(condition):
    return "yes" if condition else "NO"


low_t, low_e = min(tolerant["centroid_y"]), min(every["centroid_y"])
force_t, force_e = max(tolerant["contact_force"]), max(every["contact_force"])
print("steps: %d" % (len(tolerant["time"]) - 1))
print("lowest centroid [mm], tolerance 0.02 / 0: %.3g / %.3g"
      % (1e3 * low_t, 1e3 * low_e))
print("largest contact force [N], tolerance 0.02 / 0: %.2g / %.2g"
      % (force_t, force_e))
print("lowest centroids within 1 mm: %s" % yes(abs(low_t - low_e) < 1e-3))
print("largest forces within 5 %%: %s"
      % yes(abs(force_t - force_e) < 0.05 * force_e))
print("|volume change| below 1e-9: %s"
      % yes(max(abs(v) for v in tolerant["volume_change"]) < 1e-9))
print("no liquid below the floor: %s" % yes(min(tolerant["lower_y"]) >= 0))
print("mesh changes no more often: %s"
      % yes(sum(tolerant["mesh_changes"]) <= sum(every["mesh_changes"])))
