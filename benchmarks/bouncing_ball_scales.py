#!/usr/bin/env python3
"""The seed's two scales on the 3D ball: the surface's cells against the
flow's, each run the seed's 54 steps of prm/bouncing_ball_fine.prm with
one scale changed; the events, the wall time and where it goes.

Usage (from anywhere):
  /usr/bin/python3 benchmarks/bouncing_ball_scales.py [--vefs build/vefs]
      [--runs 5/5 2.5/5 2.5/10 [1.25/5]] [--np 2] [--end-time 1.35]
      [--results-dir benchmarks/results/bouncing_ball_scales]
      [--output benchmarks/results/bouncing_ball_scales.md] [--no-run]
      [--plot doc/bouncing_ball_3d_scales.png]

Runs (transport / flow cells in mm): 5/5 is prm/bouncing_ball_fine.prm with
'Maximum level = 2' and 'Flow cells = finest', 2.5/5 the scene itself,
2.5/10 the scene with 'Flow cells = grandparents', 1.25/5
prm/bouncing_ball_seed.prm (1.5 h on 2 ranks: not run by default).
Each run has no frames; its output goes to <results-dir>/<name>/, its log
to <name>.log, its wall time and revision to <name>.json. The page written
is doc/bouncing_ball_3d_study.md's table "All 54 steps"; --plot draws the
runs' centroid height, contact force, sheet height on the x- wall, cells,
energy and wall time against t (the page's figure).
"""
import argparse
import json
import os
import sys

from vefs_tools import REPO_ROOT as ROOT
from vefs_tools.prm import set_entry
from vefs_tools.run import (git_revision, results_directory, run_vefs,
                            vefs_command)
from vefs_tools.statistics import read_statistics
from vefs_tools.timers import timer_seconds

# name: (scene, entries changed)
RUNS = {
    "5/5": ("bouncing_ball_fine.prm",
            [(["Mesh refinement"], "Maximum level", "2"),
             (["Flow"], "Flow cells", "finest")]),
    "2.5/5": ("bouncing_ball_fine.prm", []),
    "2.5/10": ("bouncing_ball_fine.prm",
               [(["Flow"], "Flow cells", "grandparents")]),
    "1.25/5": ("bouncing_ball_seed.prm", []),
}

# timer sections in the table: (column, sections summed)
SECTIONS = [
    ("refine ahead", ["1 advection: refine ahead"]),
    ("flow setup + assembly", ["3 diffusion: setup", "3 diffusion: assembly"]),
    ("solve + contact + preconditioner",
     ["3 diffusion: solve", "3 diffusion: contact set",
      "3 diffusion: preconditioner"]),
]


def file_name(name):
    return name.replace("/", "_")


def first_local_minimum(values):
    """Index of the first step where the value stops falling (the first
    lowest centroid: the impact's, not a later settling)."""
    for k in range(1, len(values) - 1):
        if values[k] <= values[k - 1] and values[k] < values[k + 1]:
            return k
    return min(range(len(values)), key=lambda k: values[k])


def summary(s):
    """The events of one run from its statistics s."""
    t = s["time"]
    low = first_local_minimum(s["centroid_z"])
    strongest = max(range(len(t)), key=lambda k: s["contact_force"][k])
    at_wall = [tt for tt, h in zip(t, s["wall_height"]) if h > 0]
    # The ring: a hole in the liquid seen from above.
    torn = [tt for tt, area in zip(t, s.get("shadow_holes", [])) if area > 0]
    energy = s["total_energy"]
    return {
        "steps": len(t) - 1,
        "end_time": t[-1],
        "cells": int(max(s["cells"])),
        "dofs": int(max(s["dofs"])),
        "centroid": (s["centroid_z"][low], t[low]),
        "force": (s["contact_force"][strongest], t[strongest]),
        "sheet": at_wall[0] if at_wall else None,
        "ring": (torn[0] if torn else None) if "shadow_holes" in s
        else "not measured",
        "energy_left": energy[-1] / energy[0],
        "volume_change": max(abs(v) for v in s["volume_change"]),
        "lowest_point": min(s["lower_z"]),
    }


def plot(runs, png):
    """The events' quantities of each run against time, one panel each."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    # (label, values, y scale)
    panels = [
        ("centroid height [mm]",
         lambda s: [1e3 * z for z in s["centroid_z"]], "linear"),
        ("contact force [N]", lambda s: s["contact_force"], "linear"),
        ("liquid on the x- wall: highest [mm]",
         lambda s: [1e3 * h for h in s["wall_height"]], "linear"),
        ("cells of the mesh", lambda s: s["cells"], "log"),
        ("energy / energy at t = 0",
         lambda s: [e / s["total_energy"][0] for e in s["total_energy"]],
         "linear"),
        ("wall time since the start [s]", lambda s: s["wall_time"], "linear"),
    ]
    fig, axes = plt.subplots(2, 3, figsize=(13, 6.5))
    for axis, (label, values, scale) in zip(axes.flat, panels):
        for name, s in runs:
            axis.plot(s["time"], values(s), ".-", markersize=3,
                      label="%s mm" % name)
        axis.set_xlabel("t [s]")
        axis.set_ylabel(label)
        axis.set_yscale(scale)
        axis.grid(alpha=0.3)
    axes.flat[0].legend(title="transport / flow", fontsize=8)
    fig.tight_layout()
    fig.savefig(png, dpi=100)
    print("wrote %s" % png)


def make_prm(name, end_time, output_dir):
    scene, entries = RUNS[name]
    with open(os.path.join(ROOT, "prm", scene)) as f:
        text = f.read()
    for path, entry, value in entries:
        text = set_entry(text, path, entry, value)
    text = set_entry(text, ["Time"], "End time", "%g" % end_time)
    text = set_entry(text, ["Output"], "Time interval", "0")
    text = set_entry(text, [], "Output directory", output_dir)
    return text


def table(rows, np, end_time):
    lines = [
        "# The seed's two scales on the 3D ball",
        "",
        "`benchmarks/bouncing_ball_scales.py`, `mpirun -np %d`, to t = %g s. "
        "Transport / flow: the finest cells at the surface and the flow's "
        "cells, in mm; first lowest centroid: the first step where the "
        "centroid stops falling; sheet: the first step with liquid on the "
        "x- wall; ring: the first step with a hole in the liquid seen from "
        "above (the sheet torn, statistics column shadow_holes); lowest "
        "point: the lowest liquid over all steps; peak memory: the largest "
        "resident set of one process. Timer sections in s."
        % (np, end_time),
        "",
        "| transport / flow | steps | wall [s] | peak memory of a rank [GB] "
        "| max cells | flow unknowns "
        "| first lowest centroid [mm] at [ms] | largest contact force [N] "
        "at [ms] | sheet at the walls [ms] | ring [ms] | energy left "
        "| max \\|dV/V\\| "
        "| lowest point [mm] | " +
        " | ".join(c for c, _ in SECTIONS) + " | revision |",
        "|---" * (13 + len(SECTIONS) + 1) + "|",
    ]
    for name, wall, memory, revision, timers, s in rows:
        sheet, ring = ("none" if s[event] is None else s[event]
                       if isinstance(s[event], str) else
                       "%.0f" % (1e3 * s[event])
                       for event in ("sheet", "ring"))
        cells = ["%.0f" % sum(timers.get(x, float("nan")) for x in sections)
                 for _, sections in SECTIONS]
        lines.append(
            "| %s | %d | %.0f | %.2f | %d | %d | %.2f at %.0f "
            "| %.1f at %.0f | %s | %s | %.3f | %.1e | %.2f | %s | %s |" % (
                name, s["steps"], wall, memory / 1024, s["cells"], s["dofs"],
                1e3 * s["centroid"][0], 1e3 * s["centroid"][1],
                s["force"][0], 1e3 * s["force"][1], sheet, ring,
                s["energy_left"],
                s["volume_change"], 1e3 * s["lowest_point"],
                " | ".join(cells), revision))
    return "\n".join(lines) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--vefs", default=os.path.join(ROOT, "build", "vefs"))
    parser.add_argument("--runs", nargs="+", default=["5/5", "2.5/5",
                                                      "2.5/10"],
                        choices=sorted(RUNS))
    parser.add_argument("--np", type=int, default=2)
    parser.add_argument("--end-time", type=float, default=1.35)
    parser.add_argument("--results-dir", default=os.path.join(
        ROOT, "benchmarks", "results", "bouncing_ball_scales"))
    parser.add_argument("--output", default=os.path.join(
        ROOT, "benchmarks", "results", "bouncing_ball_scales.md"))
    parser.add_argument("--no-run", action="store_true",
                        help="tabulate the runs already in --results-dir")
    parser.add_argument("--plot", metavar="PNG",
                        help="also draw the runs against time into PNG")
    args = parser.parse_args()

    results_directory(args.results_dir)
    rows = []
    series = []
    for name in args.runs:
        base = os.path.join(args.results_dir, file_name(name))
        if not args.no_run:
            prm_file = base + ".prm"
            with open(prm_file, "w") as f:
                f.write(make_prm(name, args.end_time, base))
            run = run_vefs(vefs_command(os.path.abspath(args.vefs), args.np,
                                        prm_file), base + ".log")
            if run.returncode != 0:
                print("%s failed (see %s.log)" % (name, base),
                      file=sys.stderr)
                continue
            with open(base + ".json", "w") as f:
                json.dump({"wall_time": run.wall,
                           "revision": git_revision(args.vefs),
                           "max_rss_mb": run.max_rss_mb}, f)
            print("%s: %.1f s" % (name, run.wall), flush=True)
        if not os.path.exists(os.path.join(base, "statistics")) or \
                not os.path.exists(base + ".json"):
            print("%s: no run in %s" % (name, args.results_dir),
                  file=sys.stderr)
            continue
        with open(base + ".json") as f:
            info = json.load(f)
        statistics = read_statistics(base)
        rows.append((name, info["wall_time"], info["max_rss_mb"],
                     info["revision"],
                     timer_seconds(base + ".log"), summary(statistics)))
        series.append((name, statistics))

    page = table(rows, args.np, args.end_time)
    print(page)
    os.makedirs(os.path.dirname(os.path.abspath(args.output)), exist_ok=True)
    with open(args.output, "w") as f:
        f.write(page)
    if args.plot:
        plot(series, args.plot)
    return 0 if len(rows) == len(args.runs) else 1


if __name__ == "__main__":
    sys.exit(main())
