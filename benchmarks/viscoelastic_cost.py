#!/usr/bin/env python3
"""Cost of the viscoelastic stress: a scene run as it is (Oldroyd-B liquid
or elastic solid) against the same scene as a Newtonian liquid of the same
total viscosity, compared section by section of the vefs timer.

Usage (from anywhere; standard library only):
  python3 benchmarks/viscoelastic_cost.py [--vefs build/vefs]
      [--cases waters-king shear-wave] [--repeat 1]
      [--results-dir benchmarks/results] [--output benchmarks/results/viscoelastic_cost.md]
      [--no-snapshot] [--no-run]

Cases (every run: one rank, Output/Verbose = true, Output/Interval = 0,
i.e. no visualization files, so that the timer shows the computation only):
  waters-king  prm/waters_king.prm, uniform level 3, Time step 0.01,
               End time 2 (200 steps); Newtonian: Material/Relaxation
               time = 0 (the regime switch; eta_s + eta_p = 1 is kept, so
               the viscosity is the same total viscosity);
  shear-wave   prm/shear_wave.prm as it is (level 3, Time step 0.0025,
               End time 3: 1200 steps); Newtonian: Alpha = 1, Relaxation
               time = 0, Polymer viscosity = 1 (a liquid of viscosity 1).
The Newtonian counterpart solves another problem (no elasticity), but on
the same mesh with the same number of steps; what differs in the work per
step is the stress: its transport as extra components of the advected
fields, its elimination in the assembly, its node update, and whatever the
changed flow costs the linear solver (the iteration counts are listed).

For every case and repetition the two runs alternate (stress, Newtonian,
stress, ...), so that a change of the load on the machine hits both. Each
run writes <results-dir>/cost_<case>_<variant>_r<i>.prm/.log and an output
directory; the timer table at the end of the log (TimerOutput) is parsed.
The report gives, per case, the wall time per step of the whole process
and of vefs's timer, the timer sections in ms per step for both variants
with their ratio (stress / Newtonian), the mean linear iterations per step,
and the ratio of the whole step; with --repeat N > 1 the medians of the N
repetitions. The machine has 2 cores and the other one may be busy: the
1-minute load average before each run is reported.
"""

import argparse
import datetime
import json
import os
import resource
import shlex
import statistics
import sys

from vefs_tools.prm import set_entry
from vefs_tools.run import (results_directory, resolve, rel, nproc, cpu_model,
                            git_revision, run_serial_scene, executable_id,
                            snapshot_executable)
from vefs_tools.statistics import read_statistics
from vefs_tools.timers import read_timer

COMMON = [(["Output"], "Verbose", "true"), (["Output"], "Interval", "0")]

CASES = {
    "waters-king": {
        "scene": "prm/waters_king.prm",
        "title": "Waters & King start-up flow (E = 1, beta = 1/9), level 3, "
                 "tau = 0.01, end time 2",
        "common": [(["Mesh refinement"], "Minimum level", "3"),
                   (["Mesh refinement"], "Bulk level", "3"),
                   (["Mesh refinement"], "Maximum level", "3"),
                   (["Time"], "Time step", "0.01"),
                   (["Time"], "Target CFL", "0"),
                   (["Time"], "End time", "2")],
        "newtonian": [(["Material"], "Relaxation time", "0")],
        "newtonian_text": "Relaxation time = 0 (viscosity eta_s + eta_p = 1)",
    },
    "shear-wave": {
        "scene": "prm/shear_wave.prm",
        "title": "Shear wave of the neo-Hookean solid, level 3 (h = 1/64), "
                 "tau = 0.0025, end time 3 (the scene as it is)",
        "common": [(["Time"], "Target CFL", "0")],
        "newtonian": [(["Material"], "Alpha", "1"),
                      (["Material"], "Relaxation time", "0"),
                      (["Material"], "Polymer viscosity", "1")],
        "newtonian_text": "Alpha = 1, Relaxation time = 0, Polymer "
                          "viscosity = 1 (a liquid of viscosity 1)",
    },
}

def make_prm(text, changes, output_dir):
    for path, name, value in changes:
        text = set_entry(text, path, name, value)
    return set_entry(text, [], "Output directory", output_dir)


def run_one(vefs, results, name, text):
    load = os.getloadavg()[0]
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu0 = usage.ru_utime + usage.ru_stime
    if not run_serial_scene(vefs, results, name, text):
        return None
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    info_file = os.path.join(results, name + ".json")
    with open(info_file) as f:
        info = json.load(f)
    info.update(cpu_time=usage.ru_utime + usage.ru_stime - cpu0,
                load_before=load)
    with open(info_file, "w") as f:
        json.dump(info, f)
    return info


def measure(results, name):
    """Measures of one finished run: steps, process wall time, timer total
    and sections, mean linear iterations, load before."""
    with open(os.path.join(results, name + ".json")) as f:
        info = json.load(f)
    total, sections = read_timer(os.path.join(results, name + ".log"))
    stats = read_statistics(os.path.join(results, name))
    steps = int(stats["step"][-1])
    its = [x for s, x in zip(stats["step"], stats["linear_iterations"])
           if s > 0]
    return {"steps": steps, "wall": info["wall_time"],
            "cpu": info.get("cpu_time"), "load": info.get("load_before"),
            "timer_total": total, "sections": sections,
            "mean_its": sum(its) / len(its) if its else None,
            "revision": info.get("revision"),
            "executable": info.get("executable")}


def _median(xs):
    xs = [x for x in xs if x is not None]
    return statistics.median(xs) if xs else None


def _f(fmt, x):
    return "n/a" if x is None else fmt % x


def format_case(case, reps):
    """Markdown lines of one case; reps = [(stress, newtonian)]."""
    spec = CASES[case]
    lines = ["## %s" % spec["title"], "",
             "Scene `%s`; Newtonian: %s." % (spec["scene"],
                                              spec["newtonian_text"]), ""]
    variants = ("stress", "newtonian")
    lines += ["| run | variant | steps | load before | process wall [s] | "
              "CPU [s] | timer total [s] | ms/step (timer) | mean its |",
              "|---|---|---|---|---|---|---|---|---|"]
    for k, pair in enumerate(reps):
        for v, m in zip(variants, pair):
            lines.append("| %d | %s | %d | %s | %.2f | %s | %.2f | %.2f | %s |"
                         % (k + 1, v, m["steps"], _f("%.2f", m["load"]),
                            m["wall"], _f("%.2f", m["cpu"]),
                            m["timer_total"],
                            1e3 * m["timer_total"] / m["steps"],
                            _f("%.1f", m["mean_its"])))
    lines.append("")
    names = []
    for pair in reps:
        for m in pair:
            for s in m["sections"]:
                if s not in names:
                    names.append(s)
    med = "median of %d runs, " % len(reps) if len(reps) > 1 else ""
    lines += ["Timer sections in ms per time step (%sdivided by the number "
              "of steps, also for the one-off sections):" % med, "",
              "| section | with stress | Newtonian | ratio |",
              "|---|---|---|---|"]
    rows = []
    for s in names + ["whole run (timer total)"]:
        vals = []
        for i, v in enumerate(variants):
            xs = []
            for pair in reps:
                m = pair[i]
                if s.startswith("whole run"):
                    xs.append(m["timer_total"] / m["steps"])
                elif s in m["sections"]:
                    xs.append(m["sections"][s][1] / m["steps"])
            vals.append(_median(xs))
        ratio = vals[0] / vals[1] if vals[0] is not None and vals[1] else None
        rows.append((s, vals, ratio))
        lines.append("| %s | %s | %s | %s |" % (
            s, _f("%.3f", None if vals[0] is None else 1e3 * vals[0]),
            _f("%.3f", None if vals[1] is None else 1e3 * vals[1]),
            _f("%.2f", ratio)))
    lines.append("")
    whole = rows[-1][2]
    wall = [_median([p[i]["wall"] / p[i]["steps"] for p in reps])
            for i in range(2)]
    cpu = [_median([p[i]["cpu"] / p[i]["steps"] if p[i]["cpu"] else None
                    for p in reps]) for i in range(2)]
    cpu_ratio = cpu[0] / cpu[1] if cpu[0] and cpu[1] else None
    lines.append("Ratio of the whole step, stress / Newtonian: %s (timer "
                 "total per step), %s (process wall time per step, start-up "
                 "included), %s (CPU time of the process per step)."
                 % (_f("%.2f", whole), _f("%.2f", wall[0] / wall[1]),
                    _f("%.2f", cpu_ratio)))
    lines.append("")
    return lines, (whole, cpu_ratio)


def parse_args(argv=None):
    p = argparse.ArgumentParser(
        description="Cost of the viscoelastic stress against a Newtonian "
        "run of the same scene (vefs timer sections).")
    p.add_argument("--vefs", default="build/vefs")
    p.add_argument("--cases", nargs="+", default=list(CASES),
                   choices=list(CASES))
    p.add_argument("--repeat", type=int, default=1,
                   help="runs per variant (alternating; medians reported)")
    p.add_argument("--results-dir", default="benchmarks/results")
    p.add_argument("--output", default="benchmarks/results/viscoelastic_cost.md")
    p.add_argument("--no-snapshot", action="store_true",
                   help="run --vefs itself, not a copy taken at the start")
    p.add_argument("--no-run", action="store_true",
                   help="tabulate existing runs")
    return p.parse_args(argv)


def main(argv=None):
    args = parse_args(argv)
    vefs = resolve(args.vefs)
    results = resolve(args.results_dir)
    output = resolve(args.output)
    command = " ".join(["python3", "benchmarks/viscoelastic_cost.py"] +
                       [shlex.quote(a) for a in (argv if argv is not None
                                                 else sys.argv[1:])])
    if not args.no_run:
        results_directory(results)
        # git state judged once, against the build time of the original
        revision = git_revision(vefs)
        if not args.no_snapshot:
            vefs, ident = snapshot_executable(vefs, results)
            print("running a copy of build/vefs (built %s, sha256 %s...)"
                  % (ident["built"], ident["sha256"][:12]), flush=True)
        executable = executable_id(vefs)

    text = ["# Cost of the viscoelastic stress", "",
            "Generated by `benchmarks/viscoelastic_cost.py` on %s."
            % datetime.date.today().isoformat(), "",
            "- Command: `%s`" % command,
            "- Machine: `nproc` = %s, %s; 1 rank per run. The other core may "
            "have been busy with other work (load before: 1-minute load "
            "average at the start of the run): the times are indicative."
            % (nproc(), cpu_model()),
            "- Every run: Output/Verbose = true, Output/Interval = 0 (no "
            "visualization files).", ""]
    summary = []
    all_reps = []
    failed = False
    revisions = []
    for case in args.cases:
        spec = CASES[case]
        with open(resolve(spec["scene"])) as f:
            base = f.read()
        reps = []
        for k in range(args.repeat):
            pair = []
            for variant in ("stress", "newtonian"):
                name = "cost_%s_%s_r%d" % (case, variant, k + 1)
                changes = COMMON + spec["common"] + \
                    (spec["newtonian"] if variant == "newtonian" else [])
                prm = make_prm(base, changes, os.path.join(results, name))
                if not args.no_run:
                    info = run_one(vefs, results, name, prm)
                    if info is None:
                        failed = True
                        break
                    info["executable"] = executable
                    info["revision"] = revision
                    with open(os.path.join(results, name + ".json"),
                              "w") as f:
                        json.dump(info, f)
                try:
                    pair.append(measure(results, name))
                except (OSError, ValueError, KeyError) as e:
                    print("viscoelastic_cost: %s: %s" % (name, e),
                          file=sys.stderr)
                    failed = True
                    break
            if len(pair) == 2:
                reps.append(pair)
                for m in pair:
                    if m["revision"] and m["revision"] not in revisions:
                        revisions.append(m["revision"])
        if not reps:
            text += ["## %s" % spec["title"], "", "no runs", ""]
            continue
        all_reps.append(reps)
        lines, whole = format_case(case, reps)
        text += lines
        summary.append((case, whole))
    executables = []
    for pair in [p for case_reps in all_reps for p in case_reps]:
        for m in pair:
            exe = m.get("executable")
            if exe:
                label = "built %s, sha256 %s" % (exe["built"],
                                                 exe["sha256"][:12])
                if label not in executables:
                    executables.append(label)
    text[5:5] = ["- vefs revision: %s" % ", ".join(revisions or
                                                   ["unknown"]),
                 "- Executable: %s" % ("; ".join(executables) or
                                       "not recorded")]
    text += ["## Summary", "",
             "| case | whole step, stress / Newtonian (timer) | (CPU time) |",
             "|---|---|---|"]
    text += ["| %s | %s | %s |" % (c, _f("%.2f", w), _f("%.2f", u))
             for c, (w, u) in summary]
    text.append("")
    os.makedirs(os.path.dirname(output), exist_ok=True)
    with open(output, "w") as f:
        f.write("\n".join(text))
    print("\n".join(text))
    print("(written to %s)" % rel(output))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
