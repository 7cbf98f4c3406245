#!/usr/bin/env python3
"""Refinement study of the 2D broken dam (Martin & Moyce 1952, n^2 = 2).

Usage:
  benchmarks/broken_dam_refinement.py [--vefs build/vefs] [--np 1]
      [--levels 4 5 6] [--prm prm/broken_dam_2d.prm]
      [--results-dir benchmarks/results] [--doc benchmarks/results/broken_dam_refinement.md]
      [--dry-run] [--no-run] [--a 0.05715] [--g 9.81] [--reference-dir DIR]
      [--max-shift 0.3] [--revision TEXT]

For every maximum refinement level L a copy of the prm file is written to
<results-dir>/broken_dam_2d_L<L>_np<N>.prm with
  Mesh refinement / Maximum level = L
  Mesh refinement / Bulk level    = L - 2
  Mesh refinement / Minimum level = max(L - 4, 0)
  Output directory                = <results-dir>/broken_dam_2d_L<L>_np<N>
vefs is run on it (under mpirun -np N --oversubscribe if N > 1; stdout and
stderr go to <run>.log, the wall time to <run>.json) and the run is compared
with Martin & Moyce by scripts/compare_martin_moyce.py.  The resulting
Markdown table is written to --doc and printed.

--dry-run only prints the generated prm files; --no-run skips the runs and
tabulates existing results (wall times from the .json files).
--revision records TEXT as the git revision of the executable instead of the
one derived from the working tree (for an executable built elsewhere, e.g.
from `git archive COMMIT`, while the working tree has other changes).
Relative paths are taken relative to the current directory if they exist
there, otherwise relative to the repository root.
"""

import argparse
import datetime
import json
import os
import platform
import shlex
import shutil
import sys

from vefs_tools import REPO_ROOT
from vefs_tools import martin_moyce as cmm
from vefs_tools.prm import set_entry
from vefs_tools.run import (results_directory, resolve, rel, nproc, cpu_model,
                            git_revision, executable_info, vefs_command,
                            run_vefs)

RUN_PREFIX = "broken_dam_2d"


def make_prm(text, level, output_dir):
    text = set_entry(text, ["Mesh refinement"], "Maximum level", str(level))
    text = set_entry(text, ["Mesh refinement"], "Bulk level", str(level - 2))
    text = set_entry(text, ["Mesh refinement"], "Minimum level",
                     str(max(level - 4, 0)))
    text = set_entry(text, [], "Output directory", output_dir)
    return text


def summarize(output_dir, args):
    r = cmm.analyse(output_dir, args.a, args.g, args.reference_dir,
                    args.max_shift)
    st = r["stats"]
    steps = st["step"][-1] if "step" in st else len(st["time"]) - 1
    its = [x for s, x in zip(st.get("step", []), st.get("linear_iterations",
                                                          [])) if s > 0]
    return {
        "height": r["height_max"],
        "front_raw": r["front_raw_max"],
        "shift": r["shift"],
        "front_shifted": r["front_shifted_max"],
        "volume_change": r["volume_change"],
        "steps": int(steps),
        "cells": int(st["cells"][-1]) if "cells" in st else None,
        "dofs": int(st["dofs"][-1]) if "dofs" in st else None,
        "mean_its": sum(its) / len(its) if its else None,
        "max_cfl": max(st["cfl"]) if st.get("cfl") else None,
        "cell_volume_change": (
            (st["liquid_cell_volume"][-1] - st["liquid_cell_volume"][0]) /
            st["liquid_cell_volume"][0]
            if st.get("liquid_cell_volume") and st["liquid_cell_volume"][0]
            else None),
        "t_end": r["t_end"],
    }


def _f(fmt, x):
    return "n/a" if x is None else fmt % x


# --------------------------------------------------------------------------
# main
# --------------------------------------------------------------------------

def parse_args(argv=None):
    p = argparse.ArgumentParser(
        description="Refinement study of the 2D broken dam against "
        "Martin & Moyce (1952).")
    p.add_argument("--vefs", default="build/vefs",
                   help="vefs executable (default %(default)s)")
    p.add_argument("--np", type=int, default=1,
                   help="MPI ranks (default %(default)s)")
    p.add_argument("--levels", type=int, nargs="+", default=[4, 5, 6],
                   help="maximum refinement levels (default 4 5 6)")
    p.add_argument("--prm", default="prm/broken_dam_2d.prm",
                   help="base parameter file (default %(default)s)")
    p.add_argument("--results-dir", default="benchmarks/results",
                   help="where the prm copies, logs and outputs go "
                   "(default %(default)s)")
    p.add_argument("--doc", default="benchmarks/results/broken_dam_refinement.md",
                   help="Markdown file to write (default %(default)s)")
    p.add_argument("--dry-run", action="store_true",
                   help="only print the generated prm files")
    p.add_argument("--no-run", action="store_true",
                   help="do not run vefs; tabulate existing results")
    p.add_argument("--a", type=float, default=cmm.DEFAULT_A)
    p.add_argument("--g", type=float, default=cmm.DEFAULT_G)
    p.add_argument("--reference-dir", default=cmm.DEFAULT_REFERENCE_DIR)
    p.add_argument("--max-shift", type=float, default=0.3)
    p.add_argument("--revision", default=None,
                   help="git revision to record for the executable (default: "
                   "HEAD of the working tree and its code changes)")
    return p.parse_args(argv)


def main(argv=None):
    args = parse_args(argv)
    prm_path = resolve(args.prm)
    vefs = resolve(args.vefs)
    results = os.path.abspath(args.results_dir) \
        if os.path.isabs(args.results_dir) else \
        os.path.join(REPO_ROOT, args.results_dir)
    base = None
    if not args.no_run or args.dry_run:
        with open(prm_path) as f:
            base = f.read()

    if args.dry_run:
        for level in args.levels:
            name = "%s_L%d_np%d" % (RUN_PREFIX, level, args.np)
            text = make_prm(base, level, os.path.join(results, name))
            print("# ---- %s.prm (level %d) ----" % (name, level))
            print(text)
            print("# command: %s" % " ".join(shlex.quote(c) for c in
                  vefs_command(vefs, args.np,
                               os.path.join(results, name + ".prm"))))
        return 0

    if not args.no_run and not os.access(vefs, os.X_OK):
        print("broken_dam_refinement: %s is not an executable (build first, "
              "e.g. scripts/setup.sh)" % vefs, file=sys.stderr)
        return 1

    results_directory(results)

    this_command = " ".join(
        ["python3", rel(os.path.abspath(sys.argv[0]))] +
        [shlex.quote(a) for a in (argv if argv is not None else
                                  sys.argv[1:])])
    if not args.no_run:
        # recorded in every run's .json so that --no-run can report them
        provenance = {"study_command": this_command,
                      "executable": executable_info(vefs),
                      "git_revision": (args.revision if args.revision
                                       else git_revision(vefs)),
                      "date": datetime.date.today().isoformat()}
    rows = []
    commands = []
    provenances = []
    failed = False
    for level in args.levels:
        name = "%s_L%d_np%d" % (RUN_PREFIX, level, args.np)
        out_dir = os.path.join(results, name)
        prm_file = os.path.join(results, name + ".prm")
        info_file = os.path.join(results, name + ".json")
        cmd = vefs_command(vefs, args.np, prm_file)
        cmd_text = " ".join(shlex.quote(rel(c)) for c in cmd)
        commands.append(cmd_text)
        info = {"level": level, "np": args.np, "command": cmd_text}
        if not args.no_run:
            with open(prm_file, "w") as f:
                f.write(make_prm(base, level, out_dir))
            if os.path.isdir(out_dir):
                shutil.rmtree(out_dir)
            print("running level %d: %s" % (level, cmd_text), flush=True)
            run = run_vefs(cmd, os.path.join(results, name + ".log"))
            code, wall = run.returncode, run.wall
            info.update(returncode=code, wall_time=wall, **provenance)
            with open(info_file, "w") as f:
                json.dump(info, f, indent=1)
            print("  exit code %d, wall time %.1f s" % (code, wall),
                  flush=True)
        elif os.path.exists(info_file):
            with open(info_file) as f:
                info.update(json.load(f))
        p = tuple(info.get(k, "unknown") for k in
                  ("study_command", "executable", "git_revision", "date"))
        if p not in provenances:
            provenances.append(p)
        row = {"level": level, "wall": info.get("wall_time"),
               "code": info.get("returncode")}
        try:
            row.update(summarize(out_dir, args))
        except (OSError, ValueError, KeyError) as e:
            row["error"] = str(e)
            failed = True
        if row["code"] not in (None, 0):
            failed = True
        rows.append(row)

    lines = []
    lines.append("# Broken dam (Martin & Moyce 1952, n^2 = 2): refinement "
                 "study")
    lines.append("")
    lines.append("Generated by `benchmarks/broken_dam_refinement.py`.")
    lines.append("")
    lines.append("- Machine: `nproc` = %s, %s, %s %s, Python %s"
                 % (nproc(), cpu_model(), platform.system(),
                    platform.release(), platform.python_version()))
    if args.no_run:
        lines.append("- Tabulated by: `%s`" % this_command)
    for study_command, executable, revision, date in provenances:
        lines.append("- Runs made on %s by `%s`" % (date, study_command))
        lines.append("- Executable: %s; git revision: %s"
                     % (executable, revision))
    lines.append("- vefs runs (from the repository root): " +
                 ", ".join("`%s`" % c for c in commands))
    lines.append("- Base parameter file: `%s`; Mesh refinement: Maximum "
                 "level = L, Bulk level = L-2, Minimum level = max(L-4,0)"
                 % rel(prm_path))
    lines.append("")
    lines.append("| L (min/bulk/max) | ranks | end time [s] | steps | "
                 "max CFL | final cells | final dofs | mean lin. its | "
                 "wall time [s] | H err (tau<=2) | Z err raw | shift s | "
                 "Z err shifted | volume change | liquid-cell volume change |")
    lines.append("|" + "---|" * 15)
    for r in rows:
        lv = r["level"]
        levels = "%d (%d/%d/%d)" % (lv, max(lv - 4, 0), lv - 2, lv)
        if "error" in r:
            what = "no results" if r["code"] in (None, 0) else \
                "failed (exit code %s)" % r["code"]
            lines.append("| %s | %d | %s: %s |" % (
                levels, args.np, what, r["error"].replace("|", "/")) +
                " |" * 12)
            continue
        note = "" if r["code"] in (None, 0) else \
            " (exit code %s)" % r["code"]
        lines.append("| %s | %d | %s | %d | %s | %s | %s | %s | %s | %s | "
                     "%s | %s | %s | %s | %s |" % (
                         levels, args.np, _f("%.3f", r["t_end"]) + note,
                         r["steps"], _f("%.2f", r["max_cfl"]),
                         _f("%d", r["cells"]),
                         _f("%d", r["dofs"]), _f("%.1f", r["mean_its"]),
                         _f("%.1f", r["wall"]), _f("%#.2g", r["height"]),
                         _f("%#.2g", r["front_raw"]), _f("%.3f", r["shift"]),
                         _f("%#.2g", r["front_shifted"]),
                         _f("%.2g", r["volume_change"]),
                         _f("%.2g", r["cell_volume_change"])))
    lines.append("")
    lines.append("Errors are relative: H = h/(2a) (residual height at the "
                 "wall) against tau = t sqrt(g/a) at the Martin & Moyce "
                 "points with tau <= 2; Z = z/a (surge front) against "
                 "T = t sqrt(2g/a) at the points with 1 <= T <= 3, raw and "
                 "with the simulation delayed by the fitted shift s in T "
                 "(s in [0, %g], the experiment lags because of the gate "
                 "removal). Volume change = (V_end - V_0)/V_0 of the liquid "
                 "volume from phi (kept by the volume correction); "
                 "liquid-cell volume change: the same for the total volume "
                 "of the liquid cells (the staircase domain of the Stokes "
                 "step). Wall time: the whole vefs process, including output "
                 "every 10 steps. Max CFL: largest `cfl` in the statistics. "
                 "See `scripts/compare_martin_moyce.py`." % args.max_shift)
    text = "\n".join(lines) + "\n"

    doc = os.path.abspath(args.doc) if os.path.isabs(args.doc) else \
        os.path.join(REPO_ROOT, args.doc)
    os.makedirs(os.path.dirname(doc), exist_ok=True)
    with open(doc, "w") as f:
        f.write(text)
    print()
    print(text, end="")
    print("(written to %s)" % rel(doc))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
