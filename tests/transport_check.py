"""Shared checker of the transport tests: the liquid region at the end
time against the exact final shape (the initial one: both flows bring the
liquid back). Prints the relative L1 shape error int |phi - phi_exact| / V0,
the volume change, the interface thickness (in finest cells) and a verdict
against the bounds given by the calling test."""
import math

from vefs_tools.statistics import read_statistics


def check(output_dir, max_relative_error, max_thickness):
    s = read_statistics(output_dir)
    v0 = s["volume"][0]
    error = s["shape_error"][-1] / v0
    change = s["volume_change"][-1]
    thickness = s["interface_thickness"][-1]
    print("initial volume: %.4g" % v0)
    print("final time: %.4g" % s["time"][-1])
    print("relative L1 shape error: %.3g" % error)
    print("final |volume change| below 1e-9: %s" % ("yes" if abs(change) < 1e-9 else "NO"))
    print("final interface thickness (finest cells): %.3g" % thickness)
    ok = (not math.isnan(error)) and error <= max_relative_error and thickness <= max_thickness
    print("shape error <= %g and thickness <= %g: %s"
          % (max_relative_error, max_thickness, "ok" if ok else "FAIL"))
