#!/usr/bin/env python3
"""A 3D body as shaded surfaces at selected steps, as the seed's Figures 1
and 2 (the ball and the beam at steps 3, 6, ..., 54).

Usage:
  /usr/bin/python3 scripts/render_surfaces.py OUTPUT_DIR [--steps 3,6,9]
      [--every N] [--columns 6] [--view 20,-60] [--out surfaces.png]
  /usr/bin/python3 scripts/render_surfaces.py --self-test

Reads the run's solution.pvd, .pvtu/.vtu files and statistics with numpy
only (vefs_tools/vtu.py) and draws with matplotlib (Agg, no display):
no VTK or ParaView is needed. The steps are chosen as in render_shapes.py
(default: every output of a run with 'Output/Time interval', which for
prm/bouncing_ball.prm are the seed's steps 3, 6, ..., 54).

The surface is the zero level set of the output's trilinear level set,
by marching tetrahedra (vefs_tools/isosurface.py), flat-shaded by a fixed
light from both sides; the cavity's edges are drawn thin and its floor
grey. Each panel's title gives the time (the seed's step n is at
t = n x 0.025 s), and the script prints
the volume inside the surface against the statistics' `volume` (the
flow step's cut-cell volume) for each frame: they agree to the difference
between a tetrahedral and a trilinear cut of the cells (within 0.12 %
at every frame of the 3D ball at 12.5 mm). --self-test checks the volume of a sphere under
refinement (second order).
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from render_shapes import parse_steps, select_outputs  # noqa: E402
from vefs_tools.isosurface import self_test, tetrahedra, zero_surface  # noqa: E402,E501
from vefs_tools.statistics import read_statistics  # noqa: E402
from vefs_tools.vtu import cell_rows, read_pvtu  # noqa: E402

import matplotlib  # noqa: E402
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402

#: the light's direction (towards the light) and the body's colour
LIGHT = np.array([0.3, -0.5, 0.8]) / np.linalg.norm([0.3, -0.5, 0.8])
COLOUR = np.array([0.25, 0.45, 0.75])


def surface(path):
    """Triangles, unit normals and enclosed volume of one frame."""
    mesh = read_pvtu(path, ["level_set"])
    x, v = tetrahedra(mesh.points, cell_rows(mesh),
                      mesh.point_data["level_set"])
    near = (v.min(1) < 0) & (v.max(1) >= 0) | (v.max(1) < 0)
    return zero_surface(x[near], v[near])


def draw_cavity(ax, low, high):
    """The cavity's 12 edges, thin, and its floor, light grey."""
    corners = np.array([[low[0] if i & 1 == 0 else high[0],
                         low[1] if i & 2 == 0 else high[1],
                         low[2] if i & 4 == 0 else high[2]]
                        for i in range(8)])
    for i in range(8):
        for bit in (1, 2, 4):
            if not i & bit:
                a, b = corners[i], corners[i | bit]
                ax.plot(*zip(a, b), color="0.55", lw=0.4)
    floor = corners[[0, 1, 3, 2]]
    ax.add_collection3d(Poly3DCollection([floor], facecolors=(0.85,) * 3,
                                         edgecolors="none", alpha=0.6,
                                         zorder=0))


def render(output_dir, frames, columns, view, png):
    first = read_pvtu(frames[0][3], []).points
    low, high = first.min(0), first.max(0)
    stats = read_statistics(output_dir)
    times, volumes = np.array(stats["time"]), np.array(stats["volume"])
    rows = (len(frames) + columns - 1) // columns
    fig = plt.figure(figsize=(2.4 * columns, 2.3 * rows))
    for k, (_, step, time, path) in enumerate(frames):
        triangles, normals, volume = surface(path)
        reference = volumes[np.argmin(abs(times - time))]
        print("step %d (t = %.4g): %d triangles, volume %.6g, statistics "
              "%.6g (%+.2f %%)" % (step, time, len(triangles), volume,
                                   reference,
                                   100 * (volume / reference - 1)))
        ax = fig.add_subplot(rows, columns, k + 1, projection="3d")
        # the floor below the body whatever the view (matplotlib sorts
        # whole collections by depth otherwise)
        ax.computed_zorder = False
        draw_cavity(ax, low, high)
        shade = 0.35 + 0.65 * np.abs(normals @ LIGHT)
        ax.add_collection3d(Poly3DCollection(
            triangles, facecolors=np.clip(shade[:, None] * COLOUR, 0, 1),
            edgecolors="none", linewidths=0, antialiased=False, zorder=2))
        ax.set_xlim(low[0], high[0])
        ax.set_ylim(low[1], high[1])
        ax.set_zlim(low[2], high[2])
        ax.set_box_aspect(high - low)
        ax.view_init(elev=view[0], azim=view[1])
        ax.set_axis_off()
        ax.set_title("t = %.3f s" % time, fontsize=8, pad=0)
    fig.subplots_adjust(left=0, right=1, bottom=0, top=0.93, wspace=0,
                        hspace=0.05)
    fig.savefig(png, dpi=110)
    print("wrote %s" % png)


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("output_dir", nargs="?")
    p.add_argument("--steps", help="comma separated step numbers, or "
                   "a:b:c for range(a, b + 1, c)")
    p.add_argument("--every", type=int, help="every N-th step")
    p.add_argument("--columns", type=int, default=6)
    p.add_argument("--view", default="20,-60",
                   help="elevation,azimuth of the camera in degrees")
    p.add_argument("--out", default="surfaces.png")
    p.add_argument("--self-test", action="store_true",
                   help="the volume of a sphere under refinement")
    a = p.parse_args(argv)
    if a.self_test:
        raise SystemExit(0 if self_test() else 1)
    if a.output_dir is None:
        p.error("OUTPUT_DIR is needed (or --self-test)")
    steps = parse_steps(a.steps)
    frames = select_outputs(a.output_dir, steps, a.every)
    if not frames:
        raise SystemExit("no output selected")
    view = [float(v) for v in a.view.split(",")]
    render(a.output_dir, frames, a.columns, view, a.out)


if __name__ == "__main__":
    main()
