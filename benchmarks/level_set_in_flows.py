#!/usr/bin/env python3
"""The level set's interpolation at the feet in the 2D flow scenes: each
flow test scene run with both values of 'Transport/Level set interpolation'
(linear and gradient augmented), the two runs side by side (two processes
of one rank each, so that their wall times are taken at the same load), and
each run checked by the test's own checker (tests/<scene>.py). --entry and
--values compare two values of another entry instead ('Transport/Remap
distance' 0 and 20 in doc/transport_in_flows.md).

Usage (from anywhere):
  /usr/bin/python3 benchmarks/level_set_in_flows.py [--vefs build/vefs]
      [--scenes broken_dam_2d drop_into_pool_2d ...]
      [--entry 'Transport/Level set interpolation'] [--values linear 'gradient augmented']
      [--results-dir benchmarks/results/level_set_in_flows]
      [--output benchmarks/results/level_set_in_flows.md] [--no-run]

The report lists, per scene, the wall and CPU time of each run, the ratio
of the CPU times (less sensitive to other load than the wall times) and the
lines of the checker's output that differ between the two (the measured
events, errors and energies), as doc/transport_in_flows.md quotes them.
"""
import argparse
import concurrent.futures
import os
import subprocess
import sys

from vefs_tools import REPO_ROOT as ROOT
from vefs_tools.prm import apply_settings, set_entry
from vefs_tools.run import (add_study_arguments, run_vefs, vefs_command,
                            write_report)

SCENES = ["broken_dam_2d", "broken_dam_2d_large_steps", "drop_into_pool_2d",
          "standing_wave_2d", "bouncing_ball_2d_stiff",
          "bouncing_ball_2d_soft", "oscillating_beam_2d",
          "clamped_beam_at_rest"]
ENTRY = "Transport/Level set interpolation"
PAIR = ["linear", "gradient augmented"]


def run_name(scene, value):
    """The name of a run's files in the results directory."""
    return "%s_%s" % (scene, value.replace(" ", "_"))


def run_and_record(vefs, results, name):
    """Run <results>/<name>.prm on one rank; its wall time, CPU time and
    exit status go to <name>.wall."""
    run = run_vefs(vefs_command(vefs, 1, os.path.join(results, name + ".prm")),
                   os.path.join(results, name + ".log"))
    with open(os.path.join(results, name + ".wall"), "w") as f:
        f.write("%g %g %d" % (run.wall, run.cpu, run.returncode))


def run_pair(vefs, results, scene, entry, pair, settings):
    """Both runs of `scene` at once, `entry` (SECTION/NAME) set to each
    value of `pair` (two threads, each waiting for its own vefs process)."""
    with open(os.path.join(ROOT, "tests", scene + ".prm")) as f:
        text = f.read()
    *path, entry_name = entry.split("/")
    names = []
    for value in pair:
        name = run_name(scene, value)
        prm = apply_settings(set_entry(set_entry(
            text, path, entry_name, value),
            [], "Output directory", os.path.join(results, name)), settings)
        with open(os.path.join(results, name + ".prm"), "w") as f:
            f.write(prm)
        names.append(name)
    with concurrent.futures.ThreadPoolExecutor(len(names)) as pool:
        for done in [pool.submit(run_and_record, vefs, results, name)
                     for name in names]:
            done.result()


def checked(results, scene, value):
    """(wall time, CPU time, returncode, checker lines) of one run."""
    name = run_name(scene, value)
    with open(os.path.join(results, name + ".wall")) as f:
        wall, cpu, code = f.read().split()
    checker = subprocess.run(
        [sys.executable, os.path.join(ROOT, "tests", scene + ".py"),
         os.path.join(results, name)], cwd=os.path.join(ROOT, "tests"),
        env=dict(os.environ, PYTHONPATH=os.path.join(ROOT, "scripts")),
        capture_output=True, text=True)
    lines = [l for l in checker.stdout.splitlines()
             if l.strip() and not l.lstrip()[0].isdigit()]
    if checker.returncode != 0:
        lines.append("checker failed: " + checker.stderr.strip()[-200:])
    return float(wall), float(cpu), int(code), lines


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    add_study_arguments(parser, "level_set_in_flows",
                        "level_set_in_flows.md")
    parser.add_argument("--scenes", nargs="+", default=SCENES)
    parser.add_argument("--entry", default=ENTRY,
                        help="the entry compared, SECTION/NAME")
    parser.add_argument("--values", nargs=2, default=PAIR,
                        help="its two values")
    args = parser.parse_args()
    os.makedirs(args.results_dir, exist_ok=True)
    if not args.no_run:
        for scene in args.scenes:
            run_pair(args.vefs, args.results_dir, scene, args.entry,
                     args.values, args.set)
            print(scene, "done", flush=True)
    first, second = args.values
    lines = ["# '%s' in the 2D flow tests" % args.entry, "",
             "%s / %s, run side by side on one rank each (%s)." % (
                 first, second, args.vefs), ""]
    for scene in args.scenes:
        (wall_1, cpu_1, code_1, out_1), (wall_2, cpu_2, code_2, out_2) = [
            checked(args.results_dir, scene, v) for v in args.values]
        lines.append("## %s: wall time %.1f / %.1f s, CPU time %.1f / %.1f s "
                     "(ratio %.2f)%s" % (
            scene, wall_1, wall_2, cpu_1, cpu_2, cpu_2 / cpu_1,
            "" if code_1 == code_2 == 0 else
            ", exit codes %d / %d" % (code_1, code_2)))
        lines.append("")
        for a, b in zip(out_1, out_2):
            if a != b:
                lines += ["- %s: %s" % (first, a), "- %s: %s" % (second, b)]
        lines.append("")
    write_report(args.output, lines)


if __name__ == "__main__":
    main()
