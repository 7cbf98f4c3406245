#!/usr/bin/env python3
"""Shapes of the Rider-Kothe vortex: the liquid's outline (level set 0) of
several runs at the written outputs (e.g. t = 4, the thinnest spiral, and
t = 8, back to the disk), beside the exact final shape, the initial circle
of radius 0.15 at (0.5, 0.75).

Usage:
  /usr/bin/python3 benchmarks/plot_vortex_shapes.py --run LABEL=OUTPUT_DIR
      [--run ...] [--out doc/transport_vortex_shapes.png]

Each OUTPUT_DIR is a vefs run of prm/rider_kothe_vortex.prm (or a variant)
with visualization output (e.g. 'Output/Time interval = 4'). One panel per
output time after t = 0, all runs in each; the last panel is zoomed on the
disk and shows the exact circle. Reads the files with scripts/render_shapes.py
(numpy and matplotlib only).
"""

import argparse
import math
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from vefs_tools import REPO_ROOT  # noqa: E402
from vefs_tools.vtu import (read_pvtu, read_series, cell_rows,  # noqa: E402
                            plane_data)

CENTER = (0.5, 0.75)
RADIUS = 0.15


def outline_grid(pvtu):
    mesh = read_pvtu(pvtu, ["level_set"])
    return plane_data(mesh.points, cell_rows(mesh), mesh.types,
                      mesh.point_data["level_set"], 2, None, None)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--run", action="append", required=True,
                        help="LABEL=OUTPUT_DIR (repeatable)")
    parser.add_argument("--out", default=os.path.join(
        REPO_ROOT, "doc", "transport_vortex_shapes.png"))
    args = parser.parse_args(argv)

    runs = [r.split("=", 1) for r in args.run]
    times = [t for t, _ in read_series(runs[0][1]) if t > 0]
    fig, axes = plt.subplots(1, len(times), figsize=(5 * len(times), 5))
    axes = list(axes) if len(times) > 1 else [axes]
    for ax, time in zip(axes, times):
        for k, (label, directory) in enumerate(runs):
            records = dict(read_series(directory))
            record = min(records, key=lambda t: abs(t - time))
            if abs(record - time) > 1e-9 * max(1, time):
                sys.exit("%s has no output at t = %g" % (directory, time))
            grid = outline_grid(records[record])
            ax.contour(grid[0], grid[1], grid[2], levels=[0],
                       colors=["C%d" % k], linewidths=1.2)
            ax.plot([], [], color="C%d" % k, label=label)
        last = time == times[-1]
        if last:
            s = [i * 2 * math.pi / 400 for i in range(401)]
            ax.plot([CENTER[0] + RADIUS * math.cos(a) for a in s],
                    [CENTER[1] + RADIUS * math.sin(a) for a in s],
                    "k--", linewidth=0.8, label="exact")
            ax.set_xlim(CENTER[0] - 1.2 * RADIUS, CENTER[0] + 1.2 * RADIUS)
            ax.set_ylim(CENTER[1] - 1.2 * RADIUS, CENTER[1] + 1.2 * RADIUS)
        else:
            ax.set_xlim(0, 1)
            ax.set_ylim(0, 1)
        ax.set_aspect("equal")
        ax.set_title("t = %g" % time)
        ax.legend(loc="lower left", fontsize=8)
    fig.tight_layout()
    fig.savefig(args.out, dpi=110)
    print("written", args.out)


if __name__ == "__main__":
    main()
