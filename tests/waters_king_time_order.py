#!/usr/bin/env python3
"""Checker of the waters_king_time_order test: Waters & King's start-up
flow (tests/waters_king_2d.prm) on level 2 with the second-order scheme and
the default 'Time/New force weight' (1/2 without contact walls) at tau =
0.04 and tau/2, to T = 5.

Reference: the same scene at tau = 0.0025 (the run's third directory). On
one mesh the fully discrete solution converges to the semi-discrete one as
tau -> 0, so the largest difference of the probe (centreline) velocity to
the reference over the steps is the error of the time stepping alone; the
exact solution would show the spatial error instead, which dominates from
tau = 0.02 on (doc/time_step_flow.md). The reference's own time error,
(0.0025 / 0.02)^2 = 1/64 of the half step's, moves the order by about
0.03. The observed order p = log2(e(tau) / e(tau/2)) must be at least 1.8
(2.34 measured; w = 0.51, the default with contact walls, gives 1.47, the
first-order scheme 1).

Usage: waters_king_time_order.py OUTPUT_DIR HALF_STEP_DIR REFERENCE_DIR
"""
import sys

from vefs_tools.statistics import (halving_order, largest_difference,
                                   read_statistics)

MIN_ORDER = 1.8


def main(output_dir, half_step_dir, reference_dir):
    reference = read_statistics(reference_dir)
    errors = []
    for directory in (output_dir, half_step_dir):
        run = read_statistics(directory)
        errors.append(largest_difference(run, reference, "probe_u_x"))
        print("end time %.3g, time error of the centreline velocity: %.2g"
              % (run["time"][-1], errors[-1]))
    halving_order("the time error", errors, MIN_ORDER)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2], sys.argv[3]))
