#!/usr/bin/env python3
"""The Oldroyd-B broken dam (prm/oldroyd_b_dam_2d.prm, Wi = 0.93) with its
polymer stress carried by Hookean dumbbells against the macroscopic law:
the front on the floor and the height on the x- wall at t = 0.1, 0.2,
0.25 s, for several seeds at one N_f, with the seeds' mean and its
standard error, and how many standard errors the macroscopic run lies
from the mean (doc/dumbbells.md).

Both run to t = 0.25 s with the settings dumbbells need (first-order
splitting, exponential stress update, 'Outside stress of cut cells =
extension'), one rank, no visualization output; the ensemble stress with
'Material/Dumbbell variance reduction' (--estimator reduced, the default)
or without (plain); --reuse-seeds reads the
dumbbells' runs of an earlier call and runs the macroscopic one only.

Usage (from the repository root):
  /usr/bin/python3 benchmarks/dumbbells_dam.py [--vefs build/vefs]
      [--fields 400] [--seeds 1 2 3] [--estimator reduced|plain]
      [--set 'Mesh refinement/Maximum level=7' ...]
      [--results-dir benchmarks/results/dumbbells_dam] [--no-run]
--set changes an entry in every run (the macroscopic one too), e.g. the
resolution. Another scene: --scene prm/broken_dam_3d.prm --times 0.06 0.12
0.18 --ranks 2 (with --set for its Oldroyd-B material).
"""

import argparse
import math
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, os.path.join(ROOT, "tests"))

from vefs_tools.prm import apply_settings  # noqa: E402
from vefs_tools.run import vefs_command  # noqa: E402
from vefs_tools.statistics import read_statistics  # noqa: E402

COMMON = ["Time/Scheme=first order",
          "Flow/Outside stress of cut cells=extension",
          "Stress/Stress update=exponential", "Output/Interval=0"]


def run(args, directory, settings, skip):
    if not skip:
        with open(args.scene) as f:
            text = apply_settings(
                f.read(), COMMON + ["Time/End time=%g" % max(args.times)] +
                settings + ["Output directory=" + directory])
        with open(directory + ".prm", "w") as f:
            f.write(text)
        env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1",
                   OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
        with open(directory + ".log", "w") as log:
            subprocess.run(vefs_command(args.vefs, args.ranks,
                                        directory + ".prm"),
                           stdout=log, stderr=subprocess.STDOUT, env=env,
                           check=True)
    s = read_statistics(directory)

    def at(column, t):
        i = min(range(len(s["time"])), key=lambda k: abs(s["time"][k] - t))
        return s[column][i]

    return {"front": [at("floor_extent", t) for t in args.times],
            "height": [at("wall_height", t) for t in args.times],
            "wall": s["wall_time"][-1],
            "volume": max(abs(v) for v in s["volume_change"])}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--vefs", default=os.path.join(ROOT, "build", "vefs"))
    parser.add_argument("--scene", default=os.path.join(
        ROOT, "prm", "oldroyd_b_dam_2d.prm"))
    parser.add_argument("--times", type=float, nargs="+",
                        default=[0.1, 0.2, 0.25])
    parser.add_argument("--ranks", type=int, default=1)
    parser.add_argument("--fields", type=int, default=400)
    parser.add_argument("--seeds", type=int, nargs="+", default=[1, 2, 3])
    parser.add_argument("--results-dir", default=os.path.join(
        ROOT, "benchmarks", "results", "dumbbells_dam"))
    parser.add_argument("--estimator", default="reduced",
                        choices=["reduced", "plain"])
    parser.add_argument("--set", action="append", default=[],
                        metavar="SECTION/ENTRY=VALUE")
    parser.add_argument("--no-run", action="store_true")
    parser.add_argument("--reuse-seeds", action="store_true")
    args = parser.parse_args()
    os.makedirs(args.results_dir, exist_ok=True)

    macro = run(args, os.path.join(args.results_dir, "macroscopic"),
                args.set, args.no_run)
    seeds = [run(args,
                 os.path.join(args.results_dir, "fields_%d_seed_%d_%s"
                              % (args.fields, seed, args.estimator)),
                 args.set + ["Material/Stress model=dumbbells",
                  "Material/Dumbbell fields=%d" % args.fields,
                  "Material/Dumbbell seed=%d" % seed,
                  "Material/Dumbbell variance reduction=%s"
                  % ("true" if args.estimator == "reduced" else "false")],
                 args.no_run or args.reuse_seeds)
             for seed in args.seeds]

    header = " | ".join("%s %g s" % (q, t) for q in ("front", "height")
                        for t in args.times)
    print("| run | %s | max volume change | wall time |" % header)
    print("|---|" + "---|" * (2 * len(args.times) + 2))

    def row(name, r):
        values = " | ".join("%.4f" % v for v in r["front"] + r["height"])
        print("| %s | %s | %.1e | %.0f s |" % (name, values, r["volume"],
                                              r["wall"]))

    row("macroscopic", macro)
    for seed, r in zip(args.seeds, seeds):
        row("N_f = %d, seed %d, %s" % (args.fields, seed, args.estimator), r)
    n = len(seeds)
    if n > 1:
        cells = []
        for q in ("front", "height"):
            for k in range(len(args.times)):
                values = [r[q][k] for r in seeds]
                mean = sum(values) / n
                error = math.sqrt(sum((v - mean) ** 2 for v in values)
                                  / (n - 1) / n)
                distance = abs(macro[q][k] - mean) / error if error else 0
                cells.append("%.4f ± %.4f (%.1f)" % (mean, error, distance))
        print("| mean ± standard error (macroscopic's distance in standard "
              "errors) | %s | | |" % " | ".join(cells))


if __name__ == "__main__":
    main()
