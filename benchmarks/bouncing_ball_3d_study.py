#!/usr/bin/env python3
"""The seed's 3D ball (prm/bouncing_ball.prm) at several resolutions on
several MPI ranks: wall time, cells, flow unknowns, volume change, lowest
point of the liquid, lowest centroid, largest contact force.

Usage (from anywhere):
  /usr/bin/python3 benchmarks/bouncing_ball_3d_study.py [--vefs build/vefs]
      [--levels 2 3 4] [--np 2] [--end-time 0.3]
      [--results-dir benchmarks/results/bouncing_ball_3d]
      [--output benchmarks/results/bouncing_ball_3d_study.md] [--no-run]
      [--set 'Stress/Stress theta=0.5' ...]

Each run is the scene with Maximum level = L (finest cells 0.1 m / 2^L at
the surface; Bulk level = L - 1), the given end time, without visualization
output, on --np ranks; its output goes to <results-dir>/L<L>/. The wall
time is that of the whole mpirun, set-up included.
"""
import argparse
import os
import sys

from vefs_tools import REPO_ROOT as ROOT
from vefs_tools.prm import apply_settings, set_entry
from vefs_tools.run import (add_study_arguments, run_vefs, vefs_command,
                            write_report)
from vefs_tools.statistics import read_statistics


def make_prm(text, level, end_time, output_dir, settings):
    text = apply_settings(text, settings)
    text = set_entry(text, ["Mesh refinement"], "Maximum level", str(level))
    text = set_entry(text, ["Mesh refinement"], "Bulk level", str(level - 1))
    text = set_entry(text, ["Time"], "End time", "%g" % end_time)
    text = set_entry(text, ["Output"], "Time interval", "0")
    text = set_entry(text, ["Output"], "Interval", "0")
    text = set_entry(text, [], "Output directory", output_dir)
    return text


def summary(directory):
    s = read_statistics(directory)
    t = s["time"]
    lowest = min(range(len(t)), key=lambda i: s["centroid_z"][i])
    strongest = max(range(len(t)), key=lambda i: s["contact_force"][i])
    energy = s["total_energy"]
    return {
        "end_time": t[-1],
        "steps": len(t) - 1,
        "cells": max(s["cells"]),
        "dofs": max(s["dofs"]),
        "volume_change": max(abs(v) for v in s["volume_change"]),
        "lowest_point": min(s["lower_z"]),
        "lowest_centroid": s["centroid_z"][lowest],
        "lowest_centroid_time": t[lowest],
        "contact_force": s["contact_force"][strongest],
        "contact_force_time": t[strongest],
        "energy_left": energy[-1] / energy[0],
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--levels", type=int, nargs="+", default=[2, 3, 4])
    parser.add_argument("--np", type=int, default=2)
    parser.add_argument("--end-time", type=float, default=0.3)
    add_study_arguments(parser, "bouncing_ball_3d",
                        "bouncing_ball_3d_study.md")
    args = parser.parse_args()

    os.makedirs(args.results_dir, exist_ok=True)
    with open(os.path.join(ROOT, "prm", "bouncing_ball.prm")) as f:
        base = f.read()
    rows = []
    for level in args.levels:
        name = "L%d" % level
        out = os.path.join(args.results_dir, name)
        wall_file = os.path.join(args.results_dir, name + ".wall")
        if not args.no_run:
            prm_file = os.path.join(args.results_dir, name + ".prm")
            with open(prm_file, "w") as f:
                f.write(make_prm(base, level, args.end_time, out, args.set))
            run = run_vefs(
                vefs_command(os.path.abspath(args.vefs), args.np, prm_file),
                os.path.join(args.results_dir, name + ".log"))
            wall = run.wall
            if run.returncode != 0:
                print("%s failed (see %s.log)" % (name, name), file=sys.stderr)
                continue
            with open(wall_file, "w") as f:
                f.write("%.1f\n" % wall)
            print("%s: %.1f s" % (name, wall), flush=True)
        if not os.path.exists(os.path.join(out, "statistics")):
            continue
        wall = float(open(wall_file).read()) if os.path.exists(wall_file) \
            else float("nan")
        rows.append((level, wall, summary(out)))

    lines = [
        "# The seed's 3D ball: resolution study",
        "",
        "Scene `prm/bouncing_ball.prm` (the seed's data, G = 20 Pa), run by "
        "`benchmarks/bouncing_ball_3d_study.py` with `mpirun -np %d` to "
        "t = %g s. h: finest cells at the surface. Heights in mm, times in "
        "ms; lowest point: the lowest liquid over all steps (below 0 would be "
        "liquid below the floor); energy left: (kinetic + potential + "
        "elastic) at the end over the start." % (args.np, args.end_time)
        + ("" if not args.set else " Changed entries: %s." % ", ".join(
            "`%s`" % x for x in args.set)),
        "",
        "| h [mm] | steps | max cells | max flow dofs | wall time [s] | "
        "max dV/V | lowest point [mm] | lowest centroid [mm] | at [ms] | "
        "largest contact force [N] | at [ms] | energy left |",
        "|---|---|---|---|---|---|---|---|---|---|---|---|",
    ]
    for level, wall, r in rows:
        lines.append(
            "| %.2f | %d | %d | %d | %.0f | %.1e | %.2f | %.1f | %.0f | %.0f "
            "| %.0f | %.2f |" % (
                100 / 2 ** level, r["steps"], r["cells"], r["dofs"], wall,
                r["volume_change"], 1000 * r["lowest_point"],
                1000 * r["lowest_centroid"],
                1000 * r["lowest_centroid_time"], r["contact_force"],
                1000 * r["contact_force_time"], r["energy_left"]))
    lines.append("")
    write_report(args.output, lines)


if __name__ == "__main__":
    main()
