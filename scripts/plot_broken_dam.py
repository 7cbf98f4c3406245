#!/usr/bin/env python3
"""Plot a 2D broken-dam run of vefs against Martin & Moyce (1952), n^2 = 2.

Usage:
  plot_broken_dam.py OUTPUT_DIR [OUTPUT_DIR ...] [-o doc/broken_dam_front.png]
                     [--shift S] [--labels L1 L2 ...] [--a 0.05715] [--g 9.81]
                     [--reference-dir DIR] [--max-shift 0.3]

Left panel: surge front Z = z/a against T = t sqrt(2g/a): the simulation as
computed (dashed), the simulation shifted by s in T (solid; s fitted as in
compare_martin_moyce.py unless --shift is given) and the experimental points.
Right panel: residual column height H = h/(2a) against tau = t sqrt(g/a).
Several output directories (e.g. of a refinement study) give several curves.
"""

import argparse
import os
import sys

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt  # noqa: E402
except ImportError as e:
    sys.exit("plot_broken_dam.py: %s; on Debian: apt-get install "
             "python3-matplotlib "
             "python3-numpy (and run the script with /usr/bin/python3)" % e)

from vefs_tools import REPO_ROOT  # noqa: E402
from vefs_tools import martin_moyce as cmm  # noqa: E402

DEFAULT_OUTPUT = os.path.join(REPO_ROOT, "doc", "broken_dam_front.png")


def _e(x):
    """Two significant digits, trailing zeros kept (0.030, not 0.03)."""
    return "n/a" if x is None else "%#.2g" % x


def parse_args(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n")[1])
    p.add_argument("output_dirs", nargs="+", metavar="OUTPUT_DIR",
                   help="vefs output directory (one or more)")
    p.add_argument("-o", "--output", default=DEFAULT_OUTPUT,
                   help="PNG file to write (default <repo>/doc/"
                   "broken_dam_front.png)")
    p.add_argument("--shift", type=float, default=None,
                   help="time shift S in T units applied to the simulated "
                   "front (default: fitted)")
    p.add_argument("--labels", nargs="+", default=None,
                   help="legend labels, one per OUTPUT_DIR")
    p.add_argument("--a", type=float, default=cmm.DEFAULT_A)
    p.add_argument("--g", type=float, default=cmm.DEFAULT_G)
    p.add_argument("--reference-dir", default=cmm.DEFAULT_REFERENCE_DIR)
    p.add_argument("--max-shift", type=float, default=0.3)
    p.add_argument("--dpi", type=int, default=150)
    return p.parse_args(argv)


def main(argv=None):
    args = parse_args(argv)
    if args.labels and len(args.labels) != len(args.output_dirs):
        print("plot_broken_dam: --labels needs one label per OUTPUT_DIR",
              file=sys.stderr)
        return 2
    (t_ref, z_ref), (tau_ref, h_ref) = cmm.load_reference(args.reference_dir)

    fig, (ax_f, ax_h) = plt.subplots(1, 2, figsize=(11, 4.5))
    colors = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    several = len(args.output_dirs) > 1
    tau_end = 0.0

    for k, d in enumerate(args.output_dirs):
        r = cmm.analyse(d, args.a, args.g, args.reference_dir, args.max_shift)
        sim = r["sim"]
        if args.shift is not None:
            s = args.shift
            err = cmm.max_error(cmm.front_errors(sim, r["front_ref"], s))
        else:
            s = r["shift"] if r["shift"] is not None else 0.0
            err = r["front_shifted_max"]
        tau_end = max(tau_end, sim["tau"][-1])
        c = colors[k % len(colors)]
        name = (args.labels[k] if args.labels else
                os.path.basename(os.path.normpath(d)) if several else "vefs")
        ax_f.plot(sim["T"], sim["Z"], "--", color=c, lw=1.2,
                  label="%s, raw" % name)
        ax_f.plot([x + s for x in sim["T"]], sim["Z"], "-", color=c, lw=1.6,
                  label="%s, shifted by %.3f (max err %s)"
                  % (name, s, _e(err)))
        ax_h.plot(sim["tau"], sim["H"], "-", color=c, lw=1.6,
                  label="%s (max err %s, $\\tau\\leq2$)"
                  % (name, _e(r["height_max"])))

    ax_f.plot(t_ref, z_ref, "ko", ms=5, mfc="none",
              label="Martin & Moyce (1952)")
    ax_f.axvspan(cmm.FRONT_T_MIN, cmm.FRONT_T_MAX, color="0.95", zorder=0,
                 label="error and fit window, $%g \\leq T \\leq %g$"
                 % (cmm.FRONT_T_MIN, cmm.FRONT_T_MAX))
    ax_f.set_xlabel(r"$T = t\,\sqrt{2g/a}$")
    ax_f.set_ylabel(r"$Z = z/a$ (surge front)")
    ax_f.set_xlim(0, max(t_ref) * 1.05)
    ax_f.set_ylim(bottom=1.0 - 0.1)
    ax_f.grid(True, lw=0.3)
    ax_f.legend(fontsize=7, loc="upper left")
    ax_f.set_title("Surge front, $n^2 = 2$")

    ax_h.plot(tau_ref, h_ref, "ks", ms=5, mfc="none",
              label="Martin & Moyce (1952)")
    ax_h.axvline(cmm.HEIGHT_TAU_MAX, color="0.6", lw=0.8, ls=":",
                 label="end of error window, $\\tau = %g$"
                 % cmm.HEIGHT_TAU_MAX)
    ax_h.set_xlabel(r"$\tau = t\,\sqrt{g/a}$")
    ax_h.set_ylabel(r"$H = h/(2a)$ (residual height at the wall)")
    # the experiment goes on to tau = 7.4; show a bit beyond the runs
    ax_h.set_xlim(0, min(max(tau_ref) * 1.02, max(3.0, 1.3 * tau_end)))
    ax_h.set_ylim(0, 1.05)
    ax_h.grid(True, lw=0.3)
    ax_h.legend(fontsize=7, loc="upper right")
    ax_h.set_title("Residual column height, $n^2 = 2$")

    fig.suptitle("Broken dam, a = %.5g m: vefs vs. Martin & Moyce (1952)"
                 % args.a, fontsize=10)
    fig.tight_layout()
    out_dir = os.path.dirname(os.path.abspath(args.output))
    os.makedirs(out_dir, exist_ok=True)
    fig.savefig(args.output, dpi=args.dpi)
    print("wrote %s" % args.output)
    return 0


if __name__ == "__main__":
    sys.exit(main())
