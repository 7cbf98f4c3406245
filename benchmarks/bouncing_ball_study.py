#!/usr/bin/env python3
"""The 2D stiff ball (prm/bouncing_ball_2d_stiff.prm) at three resolutions
and two time steps: lowest centroid height and its time, lift-off time,
rebound apex, energy lost by the scheme over the bounce, wall time.

Usage (from anywhere):
  /usr/bin/python3 benchmarks/bouncing_ball_study.py [--vefs build/vefs]
      [--levels 4 5 6] [--time-steps 0.002 0.001] [--end-time 0.45]
      [--results-dir benchmarks/results/bouncing_ball_2d_stiff]
      [--output benchmarks/results/bouncing_ball_study.md] [--no-run]
      [--set 'Stress/Stress update=exponential' ...]

Each run is the scene with Maximum level = L (finest cells 0.1 m / 2^L at
the surface), Bulk level = L - 1, the given `Time step` (an upper bound:
the CFL target may shorten it) and the end time (after the lift-off),
on one rank, without visualization output; its output goes to
<results-dir>/L<L>_tau<tau>/. The events come from scripts/vefs_tools/bounce.py
(the checker of the test bouncing_ball_2d_stiff). --no-run only analyses
the runs already there.
"""
import argparse
import os

from vefs_tools import REPO_ROOT as ROOT
from vefs_tools.bounce import bounce_events
from vefs_tools.prm import apply_settings, set_entry
from vefs_tools.run import (add_study_arguments, run_serial_scene,
                            write_report)
from vefs_tools.statistics import read_statistics


def run_name(level, tau):
    return "L%d_tau%g" % (level, tau)


def make_prm(text, level, tau, end_time, output_dir, settings):
    text = apply_settings(text, settings)
    text = set_entry(text, ["Mesh refinement"], "Maximum level", str(level))
    text = set_entry(text, ["Mesh refinement"], "Bulk level", str(level - 1))
    text = set_entry(text, ["Time"], "Time step", "%g" % tau)
    text = set_entry(text, ["Time"], "End time", "%g" % end_time)
    text = set_entry(text, ["Output"], "Interval", "0")
    text = set_entry(text, [], "Output directory", output_dir)
    return text


def ms(x):
    return "-" if x is None else "%.1f" % (1000 * x)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--levels", type=int, nargs="+", default=[4, 5, 6])
    parser.add_argument("--time-steps", type=float, nargs="+",
                        default=[0.002, 0.001])
    parser.add_argument("--end-time", type=float, default=0.45)
    add_study_arguments(parser, "bouncing_ball_2d_stiff",
                        "bouncing_ball_study.md")
    args = parser.parse_args()

    os.makedirs(args.results_dir, exist_ok=True)
    with open(os.path.join(ROOT, "prm", "bouncing_ball_2d_stiff.prm")) as f:
        base = f.read()
    rows = []
    for level in args.levels:
        for tau in args.time_steps:
            name = run_name(level, tau)
            out = os.path.join(args.results_dir, name)
            if not args.no_run:
                text = make_prm(base, level, tau, args.end_time, out, args.set)
                if not run_serial_scene(os.path.abspath(args.vefs),
                                        args.results_dir, name, text):
                    continue
            if not os.path.exists(os.path.join(out, "statistics")):
                continue
            s = read_statistics(out)
            rows.append((level, tau, bounce_events(out), len(s["step"]) - 1,
                         max(s["cells"]), max(s["dofs"]), s["wall_time"][-1]))

    lines = [
        "# The 2D stiff ball: resolution and time-step study",
        "",
        "Scene `prm/bouncing_ball_2d_stiff.prm` (G = 2000 Pa, contact floor), "
        "run by `benchmarks/bouncing_ball_study.py` on one rank to t = %g s; "
        "events from `scripts/vefs_tools/bounce.py`. h: finest cells at the "
        "surface; tau: the `Time step` bound (the CFL target shortens some "
        "steps). Heights in mm, times in ms; energy lost: 1 - E(lift-off) / "
        "E(0), all of it numerical (the material has no dissipation); v: the "
        "liquid's mean vertical velocity at lift-off; contact loss: the "
        "energy the first contact removes over the kinetic energy at impact."
        % args.end_time + ("" if not args.set else
                           " Changed entries: %s." % ", ".join(
                               "`%s`" % x for x in args.set)),
        "",
        "| h [mm] | tau [ms] | steps | max cells | max flow dofs | lowest "
        "centroid [mm] | at [ms] | lift-off [ms] | v [m/s] | rebound apex "
        "[mm] | at [ms] | energy lost | contact loss | max dV/V | wall time "
        "[s] |",
        "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|",
    ]
    for level, tau, e, steps, cells, dofs, wall in rows:
        lift = e["lift_off_time"] is not None
        lines.append(
            "| %.2f | %g | %d | %d | %d | %.1f | %s | %s | %s | %s | %s | %s "
            "| %s | %.1e | %.0f |" % (
                100 / 2 ** level, 1000 * tau, steps, cells, dofs,
                1000 * e["lowest_centroid"], ms(e["lowest_centroid_time"]),
                ms(e["lift_off_time"]),
                "%.3f" % e["lift_off_velocity"] if lift else "-",
                "%.1f" % (1000 * e["apex"]) if lift else "-",
                ms(e["apex_time"]) if lift else "-",
                "%.0f %%" % (100 * (1 - e["energy_left"])) if lift else "-",
                "%.1f %%" % (100 * e["contact_loss"]) if lift else "-",
                e["max_volume_change"], wall))
    lines.append("")
    write_report(args.output, lines)


if __name__ == "__main__":
    main()
