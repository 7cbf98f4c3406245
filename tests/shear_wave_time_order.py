#!/usr/bin/env python3
"""Checker of the shear_wave_time_order test: the standing shear wave of
shear_wave_second_order (tests/shear_wave_second_order.py) on level 4 with
the second-order scheme and the default 'Time/New force weight' (1/2
without contact walls) at tau = 0.02 and tau/2, five periods.

Reference: the exact solution keeps its amplitude (scripts/vefs_tools/
shear_wave.py), so the amplitude loss per period is the scheme's error. The
trapezoidal rule of the momentum step conserves the energy of this linear
wave; what is left is second order in tau, plus a term tau h^2 of the
node-averaged stress update (doc/time_step_flow.md). The observed order
p = log2(loss(tau) / loss(tau/2)) must be at least 1.7 (1.83 measured; the
weight w = 0.51 of the new forces, the default with contact walls, which
damps by 2 pi (w - 1/2) omega tau per period, gives 1.22).

Usage: shear_wave_time_order.py OUTPUT_DIR OUTPUT_DIR_HALF_STEP
"""
import sys

from vefs_tools.shear_wave import analyse_run
from vefs_tools.statistics import halving_order

MIN_ORDER = 1.7


def main(output_dir, half_step_dir):
    losses = []
    for directory in (output_dir, half_step_dir):
        r = analyse_run(directory)
        losses.append(r["loss_per_period"])
        print("periods %.3g, amplitude loss per period: %s"
              % (r["periods"],
                 "n/a" if r["loss_per_period"] is None
                 else "%.2g" % r["loss_per_period"]))
    halving_order("the amplitude loss", losses, MIN_ORDER)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2]))
