#!/usr/bin/env python3
"""Convergence in time and space of the viscoelastic benchmarks against
their exact solutions: Waters & King's start-up Poiseuille flow of an
Oldroyd-B fluid and the standing shear wave of a neo-Hookean solid.

Usage (from anywhere; the plot needs matplotlib, i.e. Debian's python3):
  /usr/bin/python3 benchmarks/viscoelastic_convergence.py
      [--scene prm/waters_king.prm] [--case auto|waters-king|shear-wave]
      [--vefs build/vefs] [--levels L ...] [--time-steps TAU ...]
      [--end-time T] [--set SECTION/ENTRY=VALUE ...] [--tag TAG]
      [--output benchmarks/results/<scene>_convergence.md] [--plot PNG]
      [--results-dir benchmarks/results] [--t-max 10] [--no-snapshot]
      [--time-reference TAU_REF] [--no-run] [--dry-run]

For every pair (level L, time step tau) a copy of the base scene is written
to <results-dir>/<run>.prm, <run> = <scene>[_<tag>]_conv_L<L>_dt<tau>, with
  every --set SECTION/.../ENTRY=VALUE (e.g. --set "Initial liquid/Velocity=
                                    0.01*sin(2*pi*y); 0"; top-level entries
                                    without a section; applied first)
  Mesh refinement / Minimum level = Bulk level = Maximum level = L
                                    (a uniform mesh)
  Time / Time step                = tau
  Time / Target CFL               = 0      (the time step is fixed)
  Time / End time                 = --end-time (if given)
  Output / Interval               = 0      (no visualization files)
  Output directory                = <results-dir>/<run>
and run on one rank from the repository root by the helper of the other
studies (scripts/vefs_tools/run.py run_serial_scene: log in
<name>.log, wall time of the whole process and git revision of the
executable in <name>.json, to which the study adds the CPU time of the
process, the 1-minute load average before the run, the --set entries and
the build time and sha256 of the executable; the git state is judged
once, at the start). The runs use a copy of the executable taken
at the start (<results-dir>/vefs.snapshot, as in transport_benchmarks.py;
--no-snapshot runs --vefs itself), so that a rebuild during the study
neither mixes executables nor breaks a run. Defaults: the levels are the
scene's Maximum level and the next one, the time steps the scene's one,
half and a quarter of it. --tag names a variant (e.g. one made with
--set) so that its runs and report do not overwrite those of the scene.

Measures (the analysis is that of the test checkers, imported from
scripts/):
  waters-king (scripts/vefs_tools/waters_king.py compare_run): the largest
      |U_sim - U_exact| / 1.5 of the probe (centreline) velocity over the
      statistics rows with 0 < T = t/lambda <= --t-max (default 10);
  shear-wave (scripts/vefs_tools/shear_wave.py analyse_run): |frequency error|
      |w_sim - w| / w from the zero crossings, and the amplitude loss per
      period from the extrema of the full half periods.
  time error (with --time-reference TAU_REF, either case): the largest
      |u_tau(t) - u_ref(t)| of the probe velocity (statistics column
      probe_u_x) over the rows with 0 < t, u_ref a run at TAU_REF on the
      same level, interpolated linearly in t: the error of the time
      stepping alone, whose order the exact solution cannot show once the
      spatial error dominates.
The table also gives the number of steps, the largest CFL number of the
run, the wall time and CPU time of the whole process, the time per step
measured by vefs (last `wall_time` of the statistics over the steps), the
load average before the run (the wall time depends on what else runs),
the smallest eigenvalue of the conformation tensor over the run and the
largest number of points with a non-positive one (if the statistics have
these columns; that count also includes NaN eigenvalues, see
doc/viscoelastic.md).

Observed order in time: for each level, between successive time steps
tau1 > tau2 (halvings by default), p = log(e1/e2) / log(tau1/tau2), i.e.
log2 of the error ratio for a halving; the finest level is the estimate
(at coarser levels the spatial error limits the ratios).

Writes the Markdown report to --output (default
benchmarks/results/<scene>_convergence.md) and prints it; the plot (default: --output
with .png) shows each error against the wall time (one line per level)
and against tau (one line per level, with a slope-1 guide).
--no-run tabulates existing results; --dry-run prints the prm files and
commands. Relative paths: the current directory first, then the
repository root.
"""

import argparse
import datetime
import json
import math
import os
import resource
import shlex
import sys

from vefs_tools import shear_wave, waters_king
from vefs_tools.prm import (read_parameters, parameter, parameter_float,
                            set_entry, apply_settings)
from vefs_tools.run import (results_directory, resolve, rel, nproc, cpu_model,
                            git_revision, vefs_command, run_serial_scene,
                            executable_id, snapshot_executable)
from vefs_tools.statistics import largest_difference, read_statistics

CASES = {
    "waters-king": {
        "title": "Start-up Poiseuille flow of an Oldroyd-B fluid "
                 "(Waters & King 1970)",
        "measures": [("wk_error", "max error / 1.5 (0 < T <= %(t_max)g)")],
    },
    "shear-wave": {
        "title": "Standing shear wave of a neo-Hookean solid",
        "measures": [("frequency_error", "abs. frequency error"),
                     ("loss_per_period", "amplitude loss per period")],
    },
}


def run_name(stem, level, tau):
    return "%s_conv_L%d_dt%g" % (stem, level, tau)


def make_prm(text, level, tau, output_dir, end_time=None):
    for entry in ("Minimum level", "Bulk level", "Maximum level"):
        text = set_entry(text, ["Mesh refinement"], entry, str(level))
    text = set_entry(text, ["Time"], "Time step", repr(tau))
    text = set_entry(text, ["Time"], "Target CFL", "0")  # fixed tau
    if end_time is not None:
        text = set_entry(text, ["Time"], "End time", repr(end_time))
    text = set_entry(text, ["Output"], "Interval", "0")
    text = set_entry(text, [], "Output directory", output_dir)
    return text


def detect_case(scene_path, prm):
    name = os.path.basename(scene_path).lower()
    if "waters" in name or "king" in name or "poiseuille" in name:
        return "waters-king"
    if "shear" in name or "wave" in name:
        return "shear-wave"
    try:
        alpha = parameter_float(prm, "Material/Alpha")
    except (KeyError, ValueError):
        return None
    return "shear-wave" if alpha == 0 else "waters-king"


def analyse(case, out_dir, t_max):
    """Measures of one run (dict); raises on unreadable output."""
    stats = read_statistics(out_dir)
    r = {"steps": int(stats["step"][-1]) if stats.get("step") else
         len(stats.get("time", [])) - 1,
         "t_end": stats["time"][-1] if stats.get("time") else None}
    if stats.get("min_conformation_eigenvalue"):
        r["min_eigenvalue"] = min(stats["min_conformation_eigenvalue"])
    if stats.get("non_positive_conformation_points"):
        r["non_positive"] = int(max(stats["non_positive_conformation_points"]))
    if stats.get("cfl"):
        r["max_cfl"] = max(stats["cfl"])
    if stats.get("wall_time") and r["steps"] > 0:
        # vefs's own clock at the last step (set-up included), per step
        r["wall_per_step"] = stats["wall_time"][-1] / r["steps"]
    if case == "waters-king":
        w = waters_king.compare_run(out_dir, t_max)
        r.update(wk_error=w["max_error"], E=w["E"], beta=w["beta"],
                 T_end=w["T_end"], complete=w["T_end"] >= t_max * (1 - 1e-9),
                 sim_peak=w["sim_peak"], exact_peak=w["exact_peak"])
    else:
        s = shear_wave.analyse_run(out_dir)
        fe = s["frequency_error"]
        r.update(frequency_error=None if fe is None else abs(fe),
                 signed_frequency_error=fe,
                 loss_per_period=s["loss_per_period"],
                 energy_ratio=s["energy_ratio"], gamma=s["gamma"],
                 periods=s["periods"], w=s["w"])
    return r


def observed_orders(runs, level, taus, key):
    """[(tau1, tau2, p)] for successive time steps at one level; p None
    where an error is missing or not positive."""
    result = []
    ordered = sorted(taus, reverse=True)
    for t1, t2 in zip(ordered[:-1], ordered[1:]):
        e1 = runs.get((level, t1), {}).get(key)
        e2 = runs.get((level, t2), {}).get(key)
        p = None
        if e1 and e2 and e1 > 0 and e2 > 0 and t1 != t2:
            p = math.log(e1 / e2) / math.log(t1 / t2)
        result.append((t1, t2, p))
    return result


def _f(fmt, x):
    return "n/a" if x is None else fmt % x


def format_markdown(case, runs, levels, taus, info):
    spec = CASES[case]
    measures = [(k, label % info) for k, label in spec["measures"]]
    if info.get("time_reference"):
        measures.append(("time_error", "time error (probe velocity against "
                         "tau = %g)" % info["time_reference"]))
    lines = [
        "# %s: convergence" % spec["title"],
        "",
        "Generated by `benchmarks/viscoelastic_convergence.py` on %s." %
        info["date"],
        "",
        "- Base scene: `%s`; uniform meshes (Minimum = Bulk = Maximum "
        "level = L), fixed time step tau%s." %
        (info["scene"], "" if info["end_time"] is None else
         ", end time %g s" % info["end_time"]),
        "- Machine: `nproc` = %s, %s; 1 rank per run." %
        (nproc(), cpu_model()),
        "- Command: `%s`" % info["command"],
    ]
    if info.get("sets"):
        lines.append("- Scene entries changed: %s."
                     % ", ".join("`%s`" % x for x in info["sets"]))
    lines += [
        "- vefs revision: %s" % ", ".join(info["revisions"] or ["unknown"]),
        "- Executable: %s" % ("; ".join(info.get("executables") or [])
                              or "not recorded"),
        "- Wall time: the whole vefs process, one rank; the machine has 2 "
        "cores and the other one may have been busy with other work (load "
        "before: 1-minute load average when the run started), so the wall "
        "times are indicative; the CPU time (user + system of the process) "
        "suffers less from a busy machine. ms/step: vefs's own clock at "
        "the last step (set-up included) over the steps.",
        "- min eig(conformation): smallest eigenvalue of c = I + lambda "
        "sigma / eta_p (B for the solid) over the Gauss points and steps; "
        "non-positive points: largest per-step value of the column "
        "non_positive_conformation_points, which also counts points whose "
        "eigenvalue came out NaN (rounding in deal.II's closed-form 2x2 "
        "eigenvalues where c is close to I; see doc/viscoelastic.md): with "
        "a positive minimum, no point lost positivity.",
    ]
    if case == "waters-king":
        any_run = next((r for r in runs.values() if "E" in r), None)
        if any_run:
            lines.append("- E = %.3g, beta = %.3g; exact first overshoot "
                         "U = %.4f at T = %.3f."
                         % (any_run["E"], any_run["beta"],
                            any_run["exact_peak"][1],
                            any_run["exact_peak"][0]))
        lines.append("- Error: largest |U_sim - U_exact| / 1.5 of the probe "
                     "velocity (U = u / U_inf) over the statistics rows "
                     "with 0 < T <= %g (scripts/waters_king.py)."
                     % info["t_max"])
    else:
        any_run = next((r for r in runs.values() if "w" in r), None)
        if any_run:
            lines.append("- w = %.4g rad/s, shear strain amplitude gamma = "
                         "%.2g, %.3g periods simulated."
                         % (any_run["w"], any_run["gamma"],
                            any_run["periods"]))
        lines.append("- Frequency error (w_sim - w)/w from the zero "
                     "crossings of the probe velocity; amplitude loss per "
                     "period from the extrema of the full half periods; "
                     "energy ratio = (kinetic + elastic) at the end over "
                     "t = 0 (scripts/shear_wave.py).")
    lines.append("")

    header = ["L", "tau [s]", "steps", "max CFL", "wall time [s]",
              "CPU time [s]", "ms/step", "load before"]
    if case == "waters-king":
        header += ["max error / 1.5", "overshoot U (T)"]
    else:
        header += ["frequency error", "amplitude loss / period",
                   "energy ratio"]
    if info.get("time_reference"):
        header.append("time error")
    header += ["min eig(conformation)", "non-positive points"]
    lines += ["| " + " | ".join(header) + " |",
              "|" + "---|" * len(header)]
    for level in levels:
        for tau in sorted(taus, reverse=True):
            r = runs.get((level, tau))
            cells = ["%d" % level, "%g" % tau]
            if r is None or "error" in r:
                what = "not run" if r is None else r["error"]
                lines.append("| %s | %s |" % (" | ".join(cells),
                                              what.replace("|", "/")) +
                             " |" * (len(header) - 3))
                continue
            cells += ["%d" % r["steps"], _f("%.2g", r.get("max_cfl")),
                      _f("%.1f", r.get("wall_time")),
                      _f("%.1f", r.get("cpu_time")),
                      _f("%.2g", None if r.get("wall_per_step") is None
                         else 1e3 * r["wall_per_step"]),
                      _f("%.1f", r.get("load_before"))]
            if case == "waters-king":
                err = _f("%.3g", r["wk_error"])
                if not r["complete"]:
                    err += " (run ends at T = %.3g)" % r["T_end"]
                peak = r["sim_peak"]
                cells += [err, "n/a" if peak is None else
                          "%.4f (%.3f)" % (peak[1], peak[0])]
            else:
                cells += [_f("%.3g", r["signed_frequency_error"]),
                          _f("%.3g", r["loss_per_period"]),
                          _f("%.4g", r["energy_ratio"])]
            if info.get("time_reference"):
                cells.append(_f("%.3g", r.get("time_error")))
            cells += [_f("%.3g", r.get("min_eigenvalue")),
                      _f("%d", r.get("non_positive"))]
            lines.append("| " + " | ".join(cells) + " |")
    lines.append("")

    lines += ["## Observed order in time", "",
              "p = log(e1/e2) / log(tau1/tau2) between successive time "
              "steps (log2 of the error ratio for a halving); the finest "
              "level L = %d is the estimate." % max(levels), ""]
    ordered = sorted(taus, reverse=True)
    pairs = ["%g -> %g" % (a, b) for a, b in zip(ordered[:-1], ordered[1:])]
    lines += ["| measure | L | " + " | ".join(pairs) + " |",
              "|---|---|" + "---|" * len(pairs)]
    for key, label in measures:
        for level in levels:
            orders = observed_orders(runs, level, taus, key)
            lines.append("| %s | %d%s | %s |" % (
                label, level, " (finest)" if level == max(levels) else "",
                " | ".join(_f("%.2f", p) for _, _, p in orders)))
    lines.append("")
    if info.get("plot"):
        lines += ["![errors against wall time and time step](%s)"
                  % info["plot"], ""]
    return "\n".join(lines) + "\n"


def plot(case, runs, levels, taus, path, t_max):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        from matplotlib.ticker import (FormatStrFormatter, LogLocator,
                                       NullFormatter)
    except ImportError:
        print("viscoelastic_convergence: no matplotlib, %s not written (use "
              "/usr/bin/python3 with python3-matplotlib)" % rel(path),
              file=sys.stderr)
        return False
    measures = [(k, label % {"t_max": t_max})
                for k, label in CASES[case]["measures"]]
    fig, axes = plt.subplots(len(measures), 2, squeeze=False,
                             figsize=(11, 4.2 * len(measures)))
    drawn = False
    for row, (key, label) in enumerate(measures):
        ax_wall, ax_tau = axes[row]
        for level in levels:
            pts = sorted((tau, runs[(level, tau)]) for tau in taus
                         if (level, tau) in runs and
                         runs[(level, tau)].get(key))
            pts = [(tau, r) for tau, r in pts if r[key] > 0]
            if not pts:
                continue
            drawn = True
            style = dict(marker="o", label="L = %d" % level)
            walls = sorted((r["wall_time"], r[key]) for _, r in pts
                           if r.get("wall_time"))
            if walls:
                ax_wall.loglog([w for w, _ in walls], [e for _, e in walls],
                               **style)
            ax_tau.loglog([t for t, _ in pts], [r[key] for _, r in pts],
                          **style)
        finest = [(tau, runs[(max(levels), tau)][key]) for tau in sorted(taus)
                  if (max(levels), tau) in runs and
                  runs[(max(levels), tau)].get(key)]
        finest = [(t, e) for t, e in finest if e > 0]
        if len(finest) > 1:
            t_ref, e_ref = finest[-1]
            ts = [t for t, _ in finest]
            # guide half-way below the finest level's smallest-tau error
            ax_tau.loglog(ts, [0.5 * e_ref * t / t_ref for t in ts],
                          color="gray", linestyle=":", linewidth=1,
                          label="slope 1")
        ax_wall.set_xlabel("wall time of the run [s] (1 rank)")
        ax_tau.set_xlabel("time step tau [s]")
        # readable ticks on axes that span less than a decade
        ax_tau.set_xticks(sorted(taus))
        ax_wall.xaxis.set_major_locator(LogLocator(subs=(1.0, 2.0, 5.0)))
        for axis in (ax_wall.xaxis, ax_tau.xaxis):
            axis.set_major_formatter(FormatStrFormatter("%g"))
            axis.set_minor_formatter(NullFormatter())
        for ax, what in ((ax_wall, "wall time"), (ax_tau, "time step")):
            ax.set_ylabel(label)
            ax.set_title("%s against %s" % (label, what), fontsize=10)
            ax.grid(True, which="both", alpha=0.3)
            if ax.get_legend_handles_labels()[0]:
                ax.legend(fontsize=8)
    if not drawn:
        plt.close(fig)
        return False
    fig.suptitle(CASES[case]["title"])
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return True


def parse_args(argv=None):
    p = argparse.ArgumentParser(
        description="Convergence of the viscoelastic benchmarks (Waters & "
        "King, shear wave) against their exact solutions.")
    p.add_argument("--vefs", default="build/vefs",
                   help="vefs executable (default %(default)s)")
    p.add_argument("--scene", default="prm/waters_king.prm",
                   help="base scene (default %(default)s; or "
                   "prm/shear_wave.prm)")
    p.add_argument("--case", default="auto",
                   choices=["auto", "waters-king", "shear-wave"],
                   help="analysis (default: from the scene's file name, "
                   "else Material/Alpha = 0 means shear-wave)")
    p.add_argument("--levels", type=int, nargs="+",
                   help="refinement levels (default: the scene's Maximum "
                   "level and the next one)")
    p.add_argument("--time-steps", type=float, nargs="+",
                   help="time steps in s (default: the scene's, half and a "
                   "quarter of it)")
    p.add_argument("--end-time", type=float,
                   help="Time / End time of the runs (default: the "
                   "scene's)")
    p.add_argument("--set", action="append", default=[],
                   metavar="SECTION/ENTRY=VALUE",
                   help="change an entry of the scene in every run "
                   "(repeatable), e.g. --set \"Initial liquid/Velocity="
                   "0.01*sin(2*pi*y); 0\"")
    p.add_argument("--tag",
                   help="variant name: runs <scene>_<tag>_conv_..., report "
                   "benchmarks/results/<scene>_<tag>_convergence.md")
    p.add_argument("--no-snapshot", action="store_true",
                   help="run --vefs itself, not a copy taken at the start")
    p.add_argument("--output",
                   help="Markdown report (default benchmarks/results/<scene>[_<tag>]"
                   "_convergence.md)")
    p.add_argument("--plot",
                   help="PNG plot (default: --output with .png)")
    p.add_argument("--results-dir", default="benchmarks/results",
                   help="prm copies, logs and outputs (default %(default)s)")
    p.add_argument("--t-max", type=float, default=10.0,
                   help="waters-king: compare for 0 < T <= t-max "
                   "(default %(default)s)")
    p.add_argument("--time-reference", type=float, metavar="TAU_REF",
                   help="also run every level at this time step and "
                   "tabulate each run's time error against it")
    p.add_argument("--no-run", action="store_true",
                   help="do not run vefs; tabulate existing results")
    p.add_argument("--dry-run", action="store_true",
                   help="only print the prm files and commands")
    return p.parse_args(argv)


def main(argv=None):
    args = parse_args(argv)
    scene = resolve(args.scene)
    if not os.path.isfile(scene):
        print("viscoelastic_convergence: no scene %s" % args.scene,
              file=sys.stderr)
        return 1
    with open(scene) as f:
        base = f.read()
    try:
        base = apply_settings(base, args.set)
    except ValueError as e:
        print("viscoelastic_convergence: %s" % e, file=sys.stderr)
        return 1
    prm = read_parameters(scene)
    case = args.case if args.case != "auto" else detect_case(scene, prm)
    if case is None:
        print("viscoelastic_convergence: cannot tell the case of %s; give "
              "--case" % args.scene, file=sys.stderr)
        return 1
    stem = os.path.splitext(os.path.basename(scene))[0]
    if args.tag:
        stem += "_" + args.tag
    try:
        levels = args.levels or [
            int(parameter(prm, "Mesh refinement/Maximum level", scene)),
            int(parameter(prm, "Mesh refinement/Maximum level", scene)) + 1]
        tau0 = None if args.time_steps else \
            parameter_float(prm, "Time/Time step", scene)
    except (KeyError, ValueError) as e:
        print("viscoelastic_convergence: %s; give --levels and --time-steps"
              % (e.args[0] if e.args else e), file=sys.stderr)
        return 1
    taus = args.time_steps or [tau0, tau0 / 2, tau0 / 4]
    runs_taus = taus + ([args.time_reference] if args.time_reference and
                        args.time_reference not in taus else [])
    if len(set(taus)) != len(taus) or len(set(levels)) != len(levels):
        print("viscoelastic_convergence: repeated level or time step",
              file=sys.stderr)
        return 1
    output = resolve(args.output or os.path.join(
        "benchmarks", "results", "%s_convergence.md" % stem))
    plot_path = resolve(args.plot) if args.plot else \
        os.path.splitext(output)[0] + ".png"
    vefs = resolve(args.vefs)
    results = resolve(args.results_dir)
    command = " ".join(["python3", "benchmarks/viscoelastic_convergence.py"]
                       + [shlex.quote(a) for a in (
                           argv if argv is not None else sys.argv[1:])])

    if args.dry_run:
        for level in levels:
            for tau in runs_taus:
                name = run_name(stem, level, tau)
                print("# ---- %s.prm ----" % name)
                print(make_prm(base, level, tau, os.path.join(results, name),
                               args.end_time))
                print("# command: %s" % " ".join(vefs_command(
                    vefs, 1, os.path.join(results, name + ".prm"))))
        return 0

    if not args.no_run:
        if not os.access(vefs, os.X_OK):
            print("viscoelastic_convergence: %s is not an executable (build "
                  "first, e.g. scripts/setup.sh)" % vefs, file=sys.stderr)
            return 1
        results_directory(results)
        # git state judged once, against the build time of the original
        # (HEAD may move during the study; the copy does not change)
        revision = git_revision(vefs)
        if not args.no_snapshot:
            try:
                copy, ident = snapshot_executable(vefs, results)
            except RuntimeError as e:
                print("viscoelastic_convergence: %s" % e, file=sys.stderr)
                return 1
            print("running a copy of %s (built %s, sha256 %s...): %s"
                  % (rel(vefs), ident["built"], ident["sha256"][:12],
                     rel(copy)), flush=True)
            vefs = copy
        executable = executable_id(vefs)

    runs = {}
    revisions = []
    executables = []
    failed = False
    for level in levels:
        for tau in runs_taus:
            name = run_name(stem, level, tau)
            out_dir = os.path.join(results, name)
            info_file = os.path.join(results, name + ".json")
            if not args.no_run:
                if os.path.exists(info_file):
                    os.remove(info_file)  # no stale record of a failed run
                load = os.getloadavg()[0]
                usage = resource.getrusage(resource.RUSAGE_CHILDREN)
                cpu0 = usage.ru_utime + usage.ru_stime
                if not run_serial_scene(
                        vefs, results, name,
                        make_prm(base, level, tau, out_dir, args.end_time)):
                    runs[(level, tau)] = {"error": "vefs failed (see %s.log)"
                                          % name}
                    failed = True
                    continue
                with open(info_file) as f:
                    info = json.load(f)
                usage = resource.getrusage(resource.RUSAGE_CHILDREN)
                info["cpu_time"] = usage.ru_utime + usage.ru_stime - cpu0
                info["load_before"] = load
                info["executable"] = executable
                info["revision"] = revision
                info["sets"] = args.set
                with open(info_file, "w") as f:
                    json.dump(info, f)
            info = {}
            if os.path.exists(info_file):
                with open(info_file) as f:
                    info = json.load(f)
            try:
                r = analyse(case, out_dir, args.t_max)
            except (OSError, ValueError, KeyError) as e:
                runs[(level, tau)] = {"error": "no results: %s" % (
                    e.args[0] if isinstance(e, KeyError) and e.args else e)}
                failed = True
                continue
            r["wall_time"] = info.get("wall_time")
            r["cpu_time"] = info.get("cpu_time")
            r["load_before"] = info.get("load_before")
            if info.get("revision") and info["revision"] not in revisions:
                revisions.append(info["revision"])
            exe = info.get("executable")
            if exe:
                label = "built %s, sha256 %s" % (exe["built"],
                                                 exe["sha256"][:12])
                if label not in executables:
                    executables.append(label)
            runs[(level, tau)] = r
    if args.time_reference:
        for level in levels:
            if "error" in runs.get((level, args.time_reference),
                                   {"error": "not run"}):
                continue
            reference = read_statistics(os.path.join(
                results, run_name(stem, level, args.time_reference)))
            for tau in taus:
                r = runs.get((level, tau))
                if r is not None and "error" not in r:
                    r["time_error"] = largest_difference(
                        read_statistics(os.path.join(
                            results, run_name(stem, level, tau))),
                        reference, "probe_u_x")

    info = {"date": datetime.date.today().isoformat(),
            "scene": rel(scene), "end_time": args.end_time,
            "command": command, "revisions": revisions, "t_max": args.t_max,
            "plot": None, "sets": args.set, "executables": executables,
            "time_reference": args.time_reference}
    os.makedirs(os.path.dirname(output), exist_ok=True)
    os.makedirs(os.path.dirname(plot_path), exist_ok=True)
    if plot(case, runs, levels, taus, plot_path, args.t_max):
        info["plot"] = os.path.relpath(plot_path, os.path.dirname(output))
    text = format_markdown(case, runs, levels, taus, info)
    with open(output, "w") as f:
        f.write(text)
    print(text, end="")
    print("(written to %s%s)" % (rel(output), "" if not info["plot"]
                                 else " and %s" % rel(plot_path)))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
