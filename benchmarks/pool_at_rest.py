#!/usr/bin/env python3
"""The pool at rest while the tutorial's drop falls into it: how each
'Transport/Volume correction shift' keeps it hydrostatic.

Usage (from anywhere):
  /usr/bin/python3 benchmarks/pool_at_rest.py [--vefs build/vefs]
      [--results-dir benchmarks/results/pool_at_rest]
      [--output benchmarks/results/pool_at_rest.md] [--plot pool.png]
      [--no-run] [--set SECTION/ENTRY=VALUE ...]

prm/drop_into_pool_2d.prm (finest cells 0.78 mm, 1 ms steps) to t = 0.12 s,
before the drop touches the pool, with its frames every 10 steps (0.01 s), once with each
shift, the two runs side by side on one rank each. The pool (0.2 m wide,
0.05 m deep, its surface on a mesh line) is at rest until the drop arrives:
exact, u = 0 in it and the hydrostatic pressure rho g 0.05 m = 490.5 Pa on
the floor. Reported per frame: the floor pressure's range, the largest
speed in the pool (y < 0.0499 m), the range of the level set at the nodes
of the pool's surface line y = 0.05 m; at t = 0.1 s the drop's area from
the mean velocity (the tutorial's measure, doc/tutorial.md, section 4).
"""
import argparse
import os
import sys
import threading

import numpy as np

from vefs_tools import REPO_ROOT as ROOT
from vefs_tools.prm import apply_settings, set_entry
from vefs_tools.run import add_study_arguments, run_vefs, vefs_command, \
    write_report
from vefs_tools.statistics import read_statistics
from vefs_tools.vtu import read_pvtu, read_series

SHIFTS = ["uniform", "surface speed"]
RHO_G_DEPTH = 1000 * 9.81 * 0.05
POOL_AREA = 0.2 * 0.05


def run_name(shift):
    return shift.replace(" ", "_")


def write_prm(results, shift, settings):
    with open(os.path.join(ROOT, "prm", "drop_into_pool_2d.prm")) as f:
        prm = f.read()
    prm = set_entry(prm, [], "Output directory",
                    os.path.join(results, run_name(shift)))
    prm = set_entry(prm, ["Time"], "End time", "0.12")
    prm = set_entry(prm, ["Transport"], "Volume correction shift", shift)
    path = os.path.join(results, run_name(shift) + ".prm")
    with open(path, "w") as f:
        f.write(apply_settings(prm, settings))
    return path


def frame_measures(path):
    """Floor pressure range, largest pool speed, level set range on the
    pool's surface line, for one frame."""
    mesh = read_pvtu(path, ["pressure", "velocity", "level_set"])
    points = np.asarray(mesh.points)
    pressure = np.asarray(mesh.point_data["pressure"])
    speed = np.linalg.norm(np.asarray(mesh.point_data["velocity"]), axis=1)
    psi = np.asarray(mesh.point_data["level_set"])
    y = points[:, 1]
    floor = np.abs(y) < 1e-9
    line = np.abs(y - 0.05) < 1e-9
    return (pressure[floor].min(), pressure[floor].max(),
            speed[y < 0.0499].max(), psi[line].min(), psi[line].max())


def drop_area_change(stats, t_check=0.1):
    """The drop's area from the mean velocity, -(A / V) g t, over its
    initial area, minus 1 (the pool at rest)."""
    t = stats["time"]
    n = min(range(len(t)), key=lambda i: abs(t[i] - t_check))
    volume = stats["volume"]
    area = -stats["centroid_velocity_y"][n] * volume[n] / (9.81 * t[n])
    return area / (volume[0] - POOL_AREA) - 1


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    add_study_arguments(parser, "pool_at_rest", "pool_at_rest.md")
    parser.add_argument("--plot", help="write the figure to this file")
    args = parser.parse_args()
    results = os.path.abspath(args.results_dir)
    os.makedirs(results, exist_ok=True)
    if not args.no_run:
        threads = []
        for shift in SHIFTS:
            cmd = vefs_command(args.vefs, 1,
                               write_prm(results, shift, args.set))
            log = os.path.join(results, run_name(shift) + ".log")
            threads.append(threading.Thread(target=run_vefs,
                                            args=(cmd, log)))
            threads[-1].start()
        for thread in threads:
            thread.join()

    lines = ["# The pool at rest beside the falling drop", "",
             "prm/drop_into_pool_2d.prm to 0.12 s, one rank per run "
             "(`benchmarks/pool_at_rest.py`). Exact: u = 0 in the pool, "
             "floor pressure %.1f Pa." % RHO_G_DEPTH, "",
             "| shift | t [s] | floor pressure [Pa] | largest speed in the "
             "pool [m/s] | level set on the pool's surface line [m] |",
             "|---|---|---|---|---|"]
    series = {}
    for shift in SHIFTS:
        out = os.path.join(results, run_name(shift))
        if not os.path.isdir(out):
            sys.exit("no run in %s: run without --no-run" % out)
        rows = [(t,) + frame_measures(path) for t, path in read_series(out)]
        if not rows:
            sys.exit("no frames in %s: run without --no-run" % out)
        series[shift] = rows
        for t, p_lo, p_hi, speed, psi_lo, psi_hi in rows[4::4]:
            lines.append("| %s | %.2f | %.1f-%.1f | %.1e | %.1e to %.1e |"
                         % (shift, t, p_lo, p_hi, speed, psi_lo, psi_hi))
        lines.append("| %s | drop's area at 0.1 s | %+.3f %% | | |"
                     % (shift, 100 * drop_area_change(read_statistics(out))))
    write_report(args.output, lines)

    if args.plot:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, (left, right) = plt.subplots(1, 2, figsize=(10, 3.8))
        for shift, colour in zip(SHIFTS, ["C0", "C3"]):
            rows = np.array(series[shift])
            left.fill_between(rows[:, 0], rows[:, 1], rows[:, 2],
                              color=colour, alpha=0.3)
            left.plot(rows[:, 0], rows[:, 1], color=colour, label=shift)
            right.semilogy(rows[:, 0], rows[:, 3], color=colour, label=shift)
        left.axhline(RHO_G_DEPTH, color="k", ls=":", label="hydrostatic")
        left.set_xlabel("t [s]")
        left.set_ylabel("floor pressure [Pa] (range)")
        left.legend()
        right.set_xlabel("t [s]")
        right.set_ylabel("largest speed in the pool [m/s]")
        right.legend()
        fig.suptitle("The pool at rest while the drop falls, "
                     "'Volume correction shift'")
        fig.tight_layout()
        fig.savefig(args.plot, dpi=120)
        print("wrote %s" % args.plot)


if __name__ == "__main__":
    main()
