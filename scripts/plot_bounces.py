#!/usr/bin/env python3
"""Several runs of a bouncing scene against time, one line each: centroid
height, contact force, and the sum of the kinetic, potential and elastic
energies over its value at the start (the material keeps its energy, so
the sum's change is the scheme's). For comparing schemes or resolutions of
prm/bouncing_ball_2d_stiff.prm (doc/bouncing_ball.md); 2D or 3D as
scripts/plot_bounce.py.

Usage: /usr/bin/python3 scripts/plot_bounces.py PNG LABEL=OUTPUT_DIR ...
"""
import sys

import matplotlib

from vefs_tools.statistics import height_and_depth_unit, read_statistics

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main(png, runs):
    fig, axes = plt.subplots(1, 3, figsize=(14, 3.8))
    for label, directory in runs:
        s = read_statistics(directory)
        t = s["time"]
        height, per = height_and_depth_unit(s)
        energy = s["total_energy"]
        axes[0].plot(t, s[height], label=label)
        axes[1].plot(t, s["contact_force"], label=label)
        axes[2].plot(t, [e / energy[0] for e in energy], label=label)
    axes[0].set_ylabel("centroid height (m)")
    axes[1].set_ylabel("contact force (N%s)" % per)
    axes[2].set_ylabel("energy sum / its start")
    for ax in axes:
        ax.set_xlabel("t (s)")
        ax.grid(alpha=0.3)
    axes[0].legend()
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    print("wrote", png)


if __name__ == "__main__":
    if len(sys.argv) < 3 or any("=" not in a for a in sys.argv[2:]):
        sys.exit(__doc__.strip().splitlines()[-1])
    main(sys.argv[1], [a.split("=", 1) for a in sys.argv[2:]])
