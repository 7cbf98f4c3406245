#!/usr/bin/env python3
"""Plot the probe (centreline) velocity of Waters & King runs against
T = t / lambda, with the exact series of Waters & King (1970)
(scripts/waters_king.py; data/waters_king_1970.md).

Usage (needs matplotlib, i.e. Debian's /usr/bin/python3):
  /usr/bin/python3 scripts/plot_waters_king.py OUTPUT_DIR [OUTPUT_DIR ...]
      [--labels LABEL ...] [--t-max 10] [-o waters_king.png]

Each OUTPUT_DIR is a vefs run of a Waters & King scene (statistics with
the columns time and probe_u_x, and parameters.prm; see
scripts/waters_king.py run_parameters). The runs are grouped by their
(E, beta): one panel per pair, with the exact U(Y_probe, T) (solid black,
400 points per unit of T) and each run's U_sim = probe_u_x / U_inf; below
each panel, the error (U_sim - U_exact) / 1.5 of every run. The legend
gives each run's label (default: the directory name) and its largest
|error| / 1.5 for 0 < T <= t-max.
"""

import argparse
import os
import sys

from vefs_tools import waters_king


def main(argv=None):
    p = argparse.ArgumentParser(
        description="Probe velocity of Waters & King runs against the exact "
        "series.")
    p.add_argument("output_dirs", nargs="+", metavar="OUTPUT_DIR")
    p.add_argument("--labels", nargs="+",
                   help="one label per run (default: directory names)")
    p.add_argument("--t-max", type=float, default=10.0,
                   help="plot and compare for 0 <= T <= t-max "
                   "(default %(default)s)")
    p.add_argument("-o", "--output", default="waters_king.png",
                   help="PNG file (default %(default)s)")
    args = p.parse_args(argv)
    if args.labels and len(args.labels) != len(args.output_dirs):
        p.error("give one label per OUTPUT_DIR")
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("plot_waters_king.py: needs matplotlib (use /usr/bin/python3 "
              "with python3-matplotlib)", file=sys.stderr)
        return 1

    groups = {}  # (E, beta) -> [(label, result)]
    for i, d in enumerate(args.output_dirs):
        label = args.labels[i] if args.labels else \
            os.path.basename(os.path.normpath(d))
        try:
            r = waters_king.compare_run(d, args.t_max)
        except (OSError, ValueError, KeyError) as e:
            message = e.args[0] if isinstance(e, KeyError) and e.args else e
            print("plot_waters_king.py: %s: %s" % (d, message),
                  file=sys.stderr)
            return 1
        key = (round(r["E"], 9), round(r["beta"], 9))
        groups.setdefault(key, []).append((label, r))

    n = len(groups)
    fig, axes = plt.subplots(2, n, squeeze=False, sharex="col",
                             figsize=(6.2 * n, 6.5),
                             gridspec_kw={"height_ratios": [3, 1.3]})
    for col, ((E, beta), runs) in enumerate(groups.items()):
        ax, ax_err = axes[0][col], axes[1][col]
        Y = runs[0][1]["Y_probe"]
        series = waters_king.WatersKing(E, beta)
        m = int(400 * args.t_max)
        ts = [args.t_max * i / m for i in range(m + 1)]
        ax.plot(ts, [series.velocity(Y, t) for t in ts], color="black",
                linewidth=1.4, label="exact (Waters & King)")
        for label, r in runs:
            line, = ax.plot(r["T"], r["U_sim"], linewidth=1.0,
                            label="%s: max err %.3g" % (label,
                                                        r["max_error"]))
            ax_err.plot(r["T"], [(s - e) / waters_king.STEADY_CENTRELINE
                                 for s, e in zip(r["U_sim"], r["U_exact"])],
                        linewidth=1.0, color=line.get_color())
        ax.axhline(1.5, color="gray", linestyle=":", linewidth=0.8)
        ax.set_title("E = %.3g, beta = %.3g, probe Y = %.3g"
                     % (E, beta, Y if abs(Y) > 1e-12 else 0.0), fontsize=10)
        ax.set_ylabel("U = u / U_inf")
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=8)
        ax_err.axhline(0.0, color="black", linewidth=0.6)
        ax_err.set_xlabel("T = t / lambda")
        ax_err.set_ylabel("(U_sim - U_exact) / 1.5")
        ax_err.grid(True, alpha=0.3)
        ax_err.set_xlim(0, args.t_max)
    fig.suptitle("Start-up Poiseuille flow of an Oldroyd-B liquid: "
                 "centreline velocity")
    fig.tight_layout()
    fig.savefig(args.output, dpi=110)
    plt.close(fig)
    print("written %s" % args.output)
    return 0


if __name__ == "__main__":
    sys.exit(main())
