#!/usr/bin/env python3
"""Checker of the shear_wave_second_order test: the standing shear wave of
shear_wave_2d (see tests/shear_wave_2d.py) with the default second-order
scheme. Reference: the exact frequency w = k sqrt(G/rho) and the closed
form of the scheme's phase error on this wave (doc/viscoelastic.md),
  (w_sim - w)/w = [2 atan(w tau/2)/(w tau) - 1] - (k h)^2/12,
the trapezoidal rule's phase error plus the dispersion of Q1 with the
node-averaged gradient; backward Euler's would be atan(w tau)/(w tau) - 1
in the first term. The measured error must lie within 0.001 of the closed
form (here -0.0142; with backward Euler's phase -0.0181).

Usage: shear_wave_second_order.py OUTPUT_DIR
"""
import math
import sys

from vefs_tools.shear_wave import analyse_run, format_report
from vefs_tools.prm import read_parameters, parameter_float, \
    parameter_floats

TOLERANCE = 1e-3


def main(output_dir):
    r = analyse_run(output_dir)
    prm = read_parameters(output_dir)
    tau = parameter_float(prm, "Time/Time step")
    level = parameter_float(prm, "Mesh refinement/Maximum level")
    cells = parameter_floats(prm, "Cavity/Coarse subdivisions")[1]
    h = r["L_y"] / cells / 2 ** level
    x = r["w"] * tau
    predicted = 2 * math.atan(x / 2) / x - 1 - (r["k"] * h) ** 2 / 12
    for line in format_report(r):
        print(line)
    print("closed form of the second-order scheme: %.3g" % predicted)
    ok = r["frequency_error"] is not None and \
        abs(r["frequency_error"] - predicted) <= TOLERANCE
    print("frequency error within %g of it: %s"
          % (TOLERANCE, "yes" if ok else "NO"))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
