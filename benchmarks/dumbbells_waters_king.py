#!/usr/bin/env python3
"""Hookean dumbbells (Brownian configuration fields) against the
macroscopic Oldroyd-B law: start-up of planar Poiseuille flow (Waters &
King, E = 1, beta = 1/9) on the mesh and step of tests/waters_king_2d.prm
(2 x 16 cells, Time step 0.02, T = 10: 500 steps, first-order scheme).

Usage (from the repository root):
  /usr/bin/python3 benchmarks/dumbbells_waters_king.py [--vefs build/vefs]
      [--fields 100 400 1600] [--seeds 1 2 3] [--estimators reduced plain]
      [--set 'Time/Time step=0.16' ...]
      [--results-dir benchmarks/results/dumbbells]
      [--plot doc/dumbbells_waters_king.png] [--no-run]

--set changes an entry in every run (the macroscopic one too); with a
longer step the macroscopic run's error is larger, and the dumbbells'
error meets it at fewer fields.

For every N_f, seed and estimator of the stress, one run with
'Material/Stress model = dumbbells' ('Dumbbell variance reduction' true:
reduced, false: plain), and one macroscopic run (the same scene and
scheme). Reported per run: the
error of the centreline velocity against the exact series (scripts of
tests/vefs_tools/waters_king.py), as the root mean square and the largest
|U_sim - U_exact| / 1.5 over 0 < T <= 10, and the wall time per step;
per N_f and estimator the mean over the seeds. The plot shows the
centreline velocity of the first seed at each N_f (first estimator) with
the series and the macroscopic run, and the RMS error against N_f for each
estimator with the N_f^(-1/2) slope. One rank; run it
on an otherwise idle machine for the timings.
"""

import argparse
import math
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, os.path.join(ROOT, "tests"))

from vefs_tools import waters_king  # noqa: E402
from vefs_tools.prm import apply_settings  # noqa: E402
from vefs_tools.statistics import read_statistics  # noqa: E402

SCENE = os.path.join(ROOT, "tests", "waters_king_2d.prm")
E, BETA, H, U_INF = 1.0, 1.0 / 9.0, 1.0, 1.0


def run(vefs, directory, settings, skip):
    prm = directory + ".prm"
    if not skip:
        with open(SCENE) as f:
            text = apply_settings(f.read(), settings +
                                  ["Output directory=" + directory,
                                   "Time/Scheme=first order"])
        with open(prm, "w") as f:
            f.write(text)
        with open(directory + ".log", "w") as log:
            subprocess.run([vefs, prm], stdout=log, stderr=subprocess.STDOUT,
                           check=True)
    s = read_statistics(directory)
    T = [t for t in s["time"]][1:]
    U = [u / U_INF for u in s["probe_u_x"]][1:]
    errors = [(u - waters_king.centreline(t, E, BETA)) / 1.5
              for t, u in zip(T, U)]
    rms = math.sqrt(sum(e * e for e in errors) / len(errors))
    return {"T": T, "U": U, "rms": rms, "max": max(abs(e) for e in errors),
            "per_step": s["wall_time"][-1] / (len(s["step"]) - 1)}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--vefs", default=os.path.join(ROOT, "build", "vefs"))
    parser.add_argument("--fields", type=int, nargs="+",
                        default=[100, 400, 1600])
    parser.add_argument("--seeds", type=int, nargs="+", default=[1, 2, 3])
    parser.add_argument("--estimators", nargs="+", default=["reduced", "plain"],
                        choices=["reduced", "plain"])
    parser.add_argument("--results-dir", default=os.path.join(
        ROOT, "benchmarks", "results", "dumbbells"))
    parser.add_argument("--plot",
                        default=os.path.join(ROOT, "doc",
                                             "dumbbells_waters_king.png"))
    parser.add_argument("--set", action="append", default=[],
                        metavar="SECTION/ENTRY=VALUE")
    parser.add_argument("--no-run", action="store_true",
                        help="only read the results of an earlier run")
    args = parser.parse_args()
    os.makedirs(args.results_dir, exist_ok=True)

    macroscopic = run(args.vefs, os.path.join(args.results_dir, "macroscopic"),
                      args.set, args.no_run)
    print("| run | RMS error | max error | wall time per step |")
    print("|---|---|---|---|")
    print("| macroscopic | %.3g | %.3g | %.1f ms |"
          % (macroscopic["rms"], macroscopic["max"],
             1e3 * macroscopic["per_step"]))
    by_fields = {}
    for estimator in args.estimators:
        for n in args.fields:
            for seed in args.seeds:
                name = "fields_%d_seed_%d_%s" % (n, seed, estimator)
                r = run(args.vefs, os.path.join(args.results_dir, name),
                        args.set + ["Material/Stress model=dumbbells",
                         "Material/Dumbbell fields=%d" % n,
                         "Material/Dumbbell seed=%d" % seed,
                         "Material/Dumbbell variance reduction=%s"
                         % ("true" if estimator == "reduced" else "false")],
                        args.no_run)
                by_fields.setdefault((estimator, n), []).append(r)
                print("| %s, N_f = %d, seed %d | %.3g | %.3g | %.1f ms |"
                      % (estimator, n, seed, r["rms"], r["max"],
                         1e3 * r["per_step"]))
    print()
    print("| estimator | N_f | mean RMS error | mean max error | "
          "wall time per step |")
    print("|---|---|---|---|---|")
    means = {}
    for (estimator, n), runs in by_fields.items():
        means[(estimator, n)] = sum(r["rms"] for r in runs) / len(runs)
        print("| %s | %d | %.3g | %.3g | %.1f ms |"
              % (estimator, n, means[(estimator, n)],
                 sum(r["max"] for r in runs) / len(runs),
                 1e3 * sum(r["per_step"] for r in runs) / len(runs)))

    if args.plot:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4))
        T = [0.02 * i for i in range(1, 501)]
        left.plot(T, [waters_king.centreline(t, E, BETA) for t in T], "k-",
                  lw=2, label="exact (Waters & King)")
        left.plot(macroscopic["T"], macroscopic["U"], "k--",
                  label="macroscopic")
        for (estimator, n), runs in by_fields.items():
            if estimator == args.estimators[0]:
                left.plot(runs[0]["T"], runs[0]["U"], lw=0.8,
                          label="dumbbells (%s), N_f = %d" % (estimator, n))
        left.set_xlabel("T = t / lambda")
        left.set_ylabel("centreline velocity / U_inf")
        left.legend(fontsize=8)
        for estimator in args.estimators:
            ns = sorted(n for (e, n) in means if e == estimator)
            right.loglog(ns, [means[(estimator, n)] for n in ns], "o-",
                         label="dumbbells, %s (mean of %d seeds)"
                         % (estimator, len(args.seeds)))
            right.loglog(ns, [means[(estimator, ns[0])] * math.sqrt(ns[0] / n)
                              for n in ns], "k:", lw=0.8)
        right.plot([], [], "k:", lw=0.8, label="N_f^(-1/2)")
        right.axhline(macroscopic["rms"], color="k", ls="--",
                      label="macroscopic")
        right.set_xlabel("N_f")
        right.set_ylabel("RMS error of U over 0 < T <= 10, / 1.5")
        right.legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(args.plot, dpi=110)
        print("\nplot: %s" % os.path.relpath(args.plot, ROOT))


if __name__ == "__main__":
    main()
