#!/usr/bin/env python3
"""Broken dam of an Oldroyd-B liquid at several relaxation times, at the same
total viscosity eta_s + eta_p = 10 Pa s (prm/oldroyd_b_dam_2d.prm, lambda =
0 is the Newtonian liquid): the front on the floor, the elastic energy and
the smallest eigenvalue of the conformation tensor against time, plotted to
doc/oldroyd_b_dam.png, with a markdown table of the fronts on stdout.

Usage: /usr/bin/python3 benchmarks/oldroyd_b_dam.py [--vefs build/vefs]
       [--lambdas 0 0.01 0.05 0.2] [--results-dir DIR] [--no-run]
"""
import argparse
import math
import os
import sys

from vefs_tools import REPO_ROOT as ROOT
from vefs_tools.prm import set_entry
from vefs_tools.run import run_serial_scene
from vefs_tools.statistics import read_statistics, interpolate


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--vefs", default=os.path.join(ROOT, "build", "vefs"))
    parser.add_argument("--scene",
                        default=os.path.join(ROOT, "prm", "oldroyd_b_dam_2d.prm"))
    parser.add_argument("--lambdas", type=float, nargs="+",
                        default=[0, 0.01, 0.05, 0.2])
    parser.add_argument("--results-dir", default="oldroyd_b_dam_study")
    parser.add_argument("--plot", default=os.path.join(ROOT, "doc",
                                                       "oldroyd_b_dam.png"))
    parser.add_argument("--no-run", action="store_true",
                        help="only analyse the runs of --results-dir")
    args = parser.parse_args()
    args.results_dir = os.path.abspath(args.results_dir)
    os.makedirs(args.results_dir, exist_ok=True)
    with open(args.scene) as f:
        scene = f.read()

    runs = []
    for lam in args.lambdas:
        name = "lambda_%g" % lam
        output = os.path.join(args.results_dir, name)
        text = set_entry(scene, ["Material"], "Relaxation time", repr(lam))
        if lam == 0:
            # The Newtonian liquid of the same total viscosity.
            text = set_entry(text, ["Material"], "Solvent viscosity", "10")
            text = set_entry(text, ["Material"], "Polymer viscosity", "0")
        text = set_entry(text, [], "Output directory", output)
        text = set_entry(text, ["Output"], "Interval", "0")
        if not args.no_run and not run_serial_scene(args.vefs,
                                                    args.results_dir, name,
                                                    text):
            return 1
        runs.append((lam, read_statistics(output)))

    rate = math.sqrt(2 * 9.81 / 0.05715)  # sqrt(2 g / a), 1/s
    print("| lambda (s) | Wi = lambda sqrt(2g/a) | front 0.1 s (m) | "
          "front 0.2 s (m) | front 0.25 s (m) | max elastic energy (J/m) | "
          "min eig(c) | volume change |")
    print("|---|---|---|---|---|---|---|---|")
    for lam, s in runs:
        fronts = [interpolate(s["time"], s["floor_extent"], t)
                  for t in (0.1, 0.2, 0.25)]
        eig = min(s["min_conformation_eigenvalue"]) \
            if "min_conformation_eigenvalue" in s else float("nan")
        print("| %g | %.2f | %.4f | %.4f | %.4f | %.3g | %.3g | %.1e |"
              % (lam, lam * rate, fronts[0], fronts[1], fronts[2],
                 max(s["elastic_energy"]), eig,
                 max(abs(v) for v in s["volume_change"])))

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 3, figsize=(13, 3.8))
    for i, (lam, s) in enumerate(runs):
        color = "C%d" % i
        label = ("Newtonian 10 Pa s" if lam == 0
                 else "Oldroyd-B, lambda %g s (Wi %.2g)" % (lam, lam * rate))
        axes[0].plot(s["time"], s["floor_extent"], color, label=label)
        axes[1].plot(s["time"], s["elastic_energy"], color, label=label)
        if "min_conformation_eigenvalue" in s:
            axes[2].plot(s["time"], s["min_conformation_eigenvalue"], color,
                         label=label)
    axes[0].set_ylabel("front on the floor (m)")
    axes[1].set_ylabel("elastic energy (J/m)")
    axes[2].set_ylabel("smallest eigenvalue of c")
    for ax in axes:
        ax.set_xlabel("t (s)")
        ax.grid(alpha=0.3)
    axes[0].legend(fontsize=7)
    fig.suptitle("Broken dam, eta_s + eta_p = 10 Pa s (prm/oldroyd_b_dam_2d.prm)")
    fig.tight_layout()
    fig.savefig(args.plot, dpi=110)
    print("wrote %s" % args.plot)
    return 0


if __name__ == "__main__":
    sys.exit(main())
