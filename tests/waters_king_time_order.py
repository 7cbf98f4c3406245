#!/usr/bin/env python3
"""Checker of the waters_king_time_order test: Waters & King's start-up
flow (tests/waters_king_2d.prm) on level 2 with the second-order scheme and
'Time/New force weight = 0.5' at tau = 0.04 and tau/2, to T = 5.

Reference: the same scene at tau = 0.0025 (the run's third directory). On
one mesh the fully discrete solution converges to the semi-discrete one as
tau -> 0, so the largest difference of the probe (centreline) velocity to
the reference over the steps is the error of the time stepping alone; the
exact solution would show the spatial error instead, which dominates from
tau = 0.02 on (doc/time_step_flow.md). The reference's own time error,
(0.0025 / 0.02)^2 = 1/64 of the half step's, moves the order by about
0.03. The observed order p = log2(e(tau) / e(tau/2)) must be at least 1.8
(2.34 measured; the default weight w = 0.51 gives 1.47, the first-order
scheme 1).

Usage: waters_king_time_order.py OUTPUT_DIR HALF_STEP_DIR REFERENCE_DIR
"""
import math
import sys

from vefs_tools.statistics import interpolate, read_statistics

MIN_ORDER = 1.8


def time_error(directory, reference):
    """Largest |probe_u_x - reference's| over the rows with t > 0."""
    run = read_statistics(directory)
    largest = 0.0
    for t, u in zip(run["time"], run["probe_u_x"]):
        u_ref = interpolate(reference["time"], reference["probe_u_x"], t)
        if t > 0 and u_ref is not None:
            largest = max(largest, abs(u - u_ref))
    return largest, run["time"][-1]


def main(output_dir, half_step_dir, reference_dir):
    reference = read_statistics(reference_dir)
    errors = []
    for directory in (output_dir, half_step_dir):
        error, end = time_error(directory, reference)
        errors.append(error)
        print("end time %.3g, time error of the centreline velocity: %.2g"
              % (end, error))
    ok = all(e > 0 and math.isfinite(e) for e in errors)
    order = math.log2(errors[0] / errors[1]) if ok else float("nan")
    print("observed order of the time error: %.2g" % order)
    print("order at least %g: %s"
          % (MIN_ORDER, "yes" if ok and order >= MIN_ORDER else "NO"))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2], sys.argv[3]))
