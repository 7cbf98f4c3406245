#!/usr/bin/env python3
"""Checker of the slip_wall_symmetry test: the half ball on a slip floor
(sys.argv[1]) against the whole ball vibrating freely (sys.argv[2]). The
slip floor is the whole ball's plane of symmetry, so the half ball must
lose the same fraction of its kinetic + elastic energy (within 5 % of that
loss, 1.9 % measured: the extension of the fields beyond the liquid sees no
mirror image at the wall), keep the same width (within 0.1 mm, 1/60 of a
cell) and hold half the volume."""
import sys

from vefs_tools.statistics import read_statistics


def energy_lost(s):
    energy = [k + e for k, e in zip(s["kinetic_energy"], s["elastic_energy"])]
    return 1 - energy[-1] / energy[0]


half, free = (read_statistics(d) for d in sys.argv[1:3])
lost_half, lost_free = energy_lost(half), energy_lost(free)
width_half = half["upper_x"][-1] - half["lower_x"][-1]
width_free = free["upper_x"][-1] - free["lower_x"][-1]
volume_ratio = half["volume"][-1] / free["volume"][-1]
print("end time: %.3g s" % half["time"][-1])
print("energy lost, half ball on the slip floor: %.2g" % lost_half)
print("energy lost, whole ball: %.2g" % lost_free)
print("width at the end, half / whole ball: %.3f / %.3f m"
      % (width_half, width_free))
print("volume, half / whole ball: %.4f" % volume_ratio)
same_loss = abs(lost_half - lost_free) <= 0.05 * lost_free
same_width = abs(width_half - width_free) <= 1e-4
half_volume = abs(volume_ratio - 0.5) <= 1e-6
print("the same loss within 5 %%: %s" % ("yes" if same_loss else "no"))
print("the same width within 0.1 mm: %s" % ("yes" if same_width else "no"))
print("half the volume within 1e-6: %s" % ("yes" if half_volume else "no"))
sys.exit(0 if same_loss and same_width and half_volume else 1)
