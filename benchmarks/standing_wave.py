#!/usr/bin/env python3
"""Standing gravity wave (prm/standing_wave_2d.prm) at three resolutions and
two time steps against linear theory (scripts/standing_wave.py): frequency
error, numerical amplitude loss per period, wall time; a plot of the
surface height at the wall x = 0 against the exact curve.

Usage (from anywhere; the plot needs Debian's /usr/bin/python3 with
matplotlib):
  /usr/bin/python3 benchmarks/standing_wave.py [--vefs build/vefs]
      [--levels 5 6 7] [--steps-per-period 20 40] [--periods 3]
      [--results-dir benchmarks/results/standing_wave]
      [--output benchmarks/results/standing_wave.md] [--plot doc/standing_wave.png]
      [--set SECTION/ENTRY=VALUE ...] [--time-reference N] [--no-run]

Each run is the scene with Maximum level = L (Bulk level = L - 2), the time
step T/n (T the exact linear period) and the end time --periods T, on one
rank; its output goes to <results-dir>/L<L>_n<n>/. --set changes an entry
of the scene in every run (e.g. --set 'Time/Scheme=second order'). With
--time-reference N every level also runs at T/N, and the table gives each
run's time error: the largest difference of the surface height at the wall
to that run's (interpolated in time), with its observed order between
successive steps per period. --no-run only analyses the runs already
there.
"""
import argparse
import math
import os
import sys

from vefs_tools import REPO_ROOT as ROOT
from vefs_tools.prm import apply_settings, set_entry
from vefs_tools.run import run_serial_scene, write_report
from vefs_tools.standing_wave import measure, exact_wave
from vefs_tools.statistics import largest_difference, read_statistics

# The scene's exact period (g = 9.81, L = 0.1, d = 0.05).
K = math.pi / 0.1
PERIOD = 2 * math.pi / math.sqrt(9.81 * K * math.tanh(K * 0.05))


def run_name(level, n):
    return "L%d_n%d" % (level, n)


def make_prm(text, level, n, periods, output_dir):
    text = set_entry(text, ["Mesh refinement"], "Maximum level", str(level))
    text = set_entry(text, ["Mesh refinement"], "Bulk level", str(level - 2))
    text = set_entry(text, ["Time"], "Time step", "%.8g" % (PERIOD / n))
    text = set_entry(text, ["Time"], "End time",
                     "%.8g" % (periods * PERIOD * (1 + 1e-9)))
    text = set_entry(text, ["Output"], "Interval", "0")
    text = set_entry(text, [], "Output directory", output_dir)
    return text


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--vefs", default=os.path.join(ROOT, "build", "vefs"))
    parser.add_argument("--levels", type=int, nargs="+", default=[5, 6, 7])
    parser.add_argument("--steps-per-period", type=int, nargs="+",
                        default=[20, 40])
    parser.add_argument("--periods", type=float, default=3)
    parser.add_argument("--results-dir", default=os.path.join(
        ROOT, "benchmarks", "results", "standing_wave"))
    parser.add_argument("--output", default=os.path.join(
        ROOT, "benchmarks", "results", "standing_wave.md"))
    parser.add_argument("--plot", default=os.path.join(
        ROOT, "doc", "standing_wave.png"))
    parser.add_argument("--set", action="append", default=[],
                        metavar="SECTION/ENTRY=VALUE")
    parser.add_argument("--time-reference", type=int, metavar="N")
    parser.add_argument("--no-run", action="store_true")
    args = parser.parse_args()

    os.makedirs(args.results_dir, exist_ok=True)
    with open(os.path.join(ROOT, "prm", "standing_wave_2d.prm")) as f:
        base = apply_settings(f.read(), args.set)
    rows = []
    reference_only = [args.time_reference] if args.time_reference and \
        args.time_reference not in args.steps_per_period else []
    for level in args.levels:
        reference = None
        for n in reference_only + args.steps_per_period:
            name = run_name(level, n)
            out = os.path.join(args.results_dir, name)
            if not args.no_run:
                text = make_prm(base, level, n, args.periods, out)
                if not run_serial_scene(os.path.abspath(args.vefs),
                                        args.results_dir, name, text):
                    continue
            if n in reference_only:
                continue
            m = measure(out)
            s = read_statistics(out)
            steps = len(s["step"]) - 1
            time_error = None
            if args.time_reference:
                if reference is None:
                    reference = read_statistics(os.path.join(
                        args.results_dir,
                        run_name(level, args.time_reference)))
                time_error = largest_difference(s, reference, "wall_height")
            rows.append((level, n, m, s["wall_time"][-1], steps,
                         max(s["cells"]), max(s["cfl"]), time_error))

    lines = [
        "# Standing gravity wave: sharp free surface against linear theory",
        "",
        "Scene `prm/standing_wave_2d.prm` (tank L = 0.1 m, depth 0.05 m, "
        "amplitude 2 mm, water, slip walls), run by "
        "`benchmarks/standing_wave.py` on one rank; analysis "
        "`scripts/standing_wave.py`: the period from the zero crossings of "
        "the surface height at the wall x = 0, the amplitude loss per "
        "period from its extrema, divided by the exact viscous decay "
        "exp(-2 nu k^2 T) (0.07 %% per period). Exact period %.4f s." % PERIOD,
        "",
    ]
    if args.set:
        lines += ["Scene entries changed: %s." % ", ".join(
            "`%s`" % x for x in args.set), ""]
    if args.time_reference:
        lines += ["Time error: the largest difference of the surface height "
                  "at the wall to the run at T/%d on the same mesh, "
                  "(order: log2 of its ratio to the previous row's)."
                  % args.time_reference, ""]
    lines += [
        "| h | tau | steps | max cells | max CFL | frequency error | "
        "numerical amplitude loss per period | time error [m] (order) | "
        "wall time [s] |",
        "|---|---|---|---|---|---|---|---|---|",
    ]
    previous = {}
    for level, n, m, wall, steps, cells, cfl, time_error in rows:
        loss = m["amplitude_loss_per_period"]
        error = "-"
        if time_error is not None:
            error = "%.3g" % time_error
            if previous.get(level) and time_error > 0:
                error += " (%.2f)" % math.log2(previous[level] / time_error)
            previous[level] = time_error
        lines.append("| L/%d | T/%d | %d | %d | %.2g | %+.3f %% | %s | %s | "
                     "%.1f |" % (
                         2 ** level, n, steps, cells, cfl,
                         100 * m["frequency_error"],
                         "%+.2f %%" % (100 * loss) if loss is not None
                         else "-", error, wall))
    lines.append("")
    lines.append("A negative amplitude loss is a gain. The wall times were "
                 "taken on the 2-core development machine, other work "
                 "running beside. A largest CFL number far above that of "
                 "the physical wave (below 1) marks an unstable run: the "
                 "explicit surface limits tau to about 2 (h / (pi g))^(1/2) "
                 "(doc/standing_wave.md).")
    lines.append("")
    write_report(args.output, lines)

    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("no matplotlib: no plot", file=sys.stderr)
        return
    fig, ax = plt.subplots(figsize=(8, 4))
    finest = None
    for level, n, m, wall, steps, cells, cfl, _ in rows:
        out = os.path.join(args.results_dir, run_name(level, n))
        s = read_statistics(out)
        omega, decay, level_height, amplitude = exact_wave(out)
        ax.plot(s["time"], [1000 * (h - level_height) for h in
                            s["wall_height"]],
                label="h = L/%d, tau = T/%d" % (2 ** level, n), lw=1)
        finest = (omega, decay, amplitude, s["time"][-1])
    if finest:
        omega, decay, amplitude, t_end = finest
        ts = [t_end * i / 600 for i in range(601)]
        ax.plot(ts, [1000 * amplitude * math.cos(omega * t) *
                     math.exp(-decay * t) for t in ts], "k--", lw=1.5,
                label="linear theory")
    ax.set_xlabel("t [s]")
    ax.set_ylabel("surface height at x = 0 minus depth [mm]")
    ax.legend(fontsize=7, ncol=2)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(args.plot, dpi=120)
    print("plot: %s" % args.plot)


if __name__ == "__main__":
    main()
