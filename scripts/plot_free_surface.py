#!/usr/bin/env python3
"""Draw the liquid region of a 2D vefs run at a few times (small multiples).

Usage:
  plot_free_surface.py OUTPUT_DIR [-o free_surface.png] [--times t1 t2 ...]
                       [--count 6] [--columns 3] [--no-mesh] [--field NAME]

Reads OUTPUT_DIR/solution.pvd, the .pvtu records it lists and their .vtu
pieces (every MPI rank writes one piece), as deal.II writes them: XML VTK
unstructured grids whose DataArrays are "binary" (base64), zlib-compressed
(compressor="vtkZLibDataCompressor") or not, or "ascii" (decoded by
vefs_tools/vtu.py).  Only the standard library and numpy/matplotlib are used.

Every panel shows, at one output time,
  * the cells counted as liquid (liquid_fraction >= 1/2, the cells of the
    Stokes step), filled in light blue,
  * the zero contour of the level set (the free surface), as a dark line,
  * the edges of the adaptive mesh (thin grey; --no-mesh to leave out).
By default --count times spread evenly over the series are drawn
(first and last included); --times picks the output times nearest to the
given ones.
"""

import argparse
import math
import os
import sys

try:
    import numpy as np
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt  # noqa: E402
    from matplotlib.collections import PolyCollection  # noqa: E402
    from matplotlib.tri import Triangulation  # noqa: E402
    from vefs_tools.vtu import read_series, read_any, cell_list  # noqa: E402
except ImportError as e:
    sys.exit("plot_free_surface.py: %s; on Debian: apt-get install "
             "python3-matplotlib "
             "python3-numpy (and run the script with /usr/bin/python3)" % e)


# --------------------------------------------------------------------------
# drawing
# --------------------------------------------------------------------------

def _corners(cell, points):
    """The 4 corner points of a quadrilateral in counter-clockwise order
    (VTK quad order; for deal.II's higher-order Lagrange cells the first 4
    vertices are the corners as well)."""
    return points[cell[:4], :2] if len(cell) >= 4 else points[cell, :2]


def triangles(cells):
    """Split quadrilateral cells into triangles (the first 4 vertices of a
    cell are its corners in VTK order 0-1-2-3)."""
    tri = []
    for c in cells:
        if len(c) == 3:
            tri.append(c)
        else:
            tri.append([c[0], c[1], c[2]])
            tri.append([c[0], c[2], c[3]])
    return np.array(tri, dtype=np.int64)


def draw(ax, points, cells, data, time, field, mesh, box):
    polys = [_corners(c, points) for c in cells]
    if "liquid_fraction" in data:
        frac = data["liquid_fraction"]
        liquid = [p for p, c in zip(polys, cells)
                  if frac[c[0]] >= 0.5]
        ax.add_collection(PolyCollection(liquid, facecolors="#a6cee3",
                                         edgecolors="none", zorder=1))
    if mesh:
        ax.add_collection(PolyCollection(polys, facecolors="none",
                                         edgecolors="0.75", linewidths=0.15,
                                         zorder=2))
    if field in data:
        values = data[field]
        tri = Triangulation(points[:, 0], points[:, 1], triangles(cells))
        level = 0.0 if field == "level_set" else 0.5
        ax.tricontour(tri, values, levels=[level], colors="#08306b",
                      linewidths=1.0, zorder=3)
    ax.set_xlim(box[0], box[2])
    ax.set_ylim(box[1], box[3])
    ax.set_aspect("equal")
    ax.set_title("t = %.3g s" % time, fontsize=9)
    ax.tick_params(labelsize=7)


def parse_args(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n")[1])
    p.add_argument("output_dir", metavar="OUTPUT_DIR",
                   help="output directory of a 2D vefs run")
    p.add_argument("-o", "--output", default="free_surface.png",
                   help="PNG file to write (default %(default)s)")
    p.add_argument("--times", type=float, nargs="+", default=None,
                   help="output times to draw (nearest available)")
    p.add_argument("--count", type=int, default=6,
                   help="number of panels if --times is not given "
                   "(default %(default)s)")
    p.add_argument("--columns", type=int, default=3)
    p.add_argument("--field", default="level_set",
                   help="field whose contour is drawn: level_set (zero "
                   "contour) or phi (1/2 contour)")
    p.add_argument("--no-mesh", action="store_true",
                   help="do not draw the mesh edges")
    p.add_argument("--title", default=None)
    p.add_argument("--dpi", type=int, default=150)
    return p.parse_args(argv)


def main(argv=None):
    args = parse_args(argv)
    series = read_series(args.output_dir)
    if not series:
        print("plot_free_surface: no output in %s" % args.output_dir,
              file=sys.stderr)
        return 1
    if args.times:
        chosen = [min(series, key=lambda s: abs(s[0] - t))
                  for t in args.times]
    else:
        n = max(1, min(args.count, len(series)))
        idx = [round(i * (len(series) - 1) / max(n - 1, 1))
               for i in range(n)]
        chosen = [series[i] for i in sorted(set(idx))]

    frames = [(t, read_any(path)) for t, path in chosen]
    all_points = np.vstack([f[1].points for f in frames])
    if np.ptp(all_points[:, 2]) > 0:
        print("plot_free_surface: the output is 3D; only 2D runs are drawn",
              file=sys.stderr)
        return 1
    box = (all_points[:, 0].min(), all_points[:, 1].min(),
           all_points[:, 0].max(), all_points[:, 1].max())

    ncol = min(args.columns, len(frames))
    nrow = int(math.ceil(len(frames) / float(ncol)))
    width = 3.6 * ncol
    aspect = (box[3] - box[1]) / (box[2] - box[0])
    fig, axes = plt.subplots(nrow, ncol, figsize=(width,
                                                  nrow * 3.6 * aspect + 1.0),
                             squeeze=False)
    for ax, (t, mesh) in zip(axes.ravel(), frames):
        draw(ax, mesh.points, cell_list(mesh), mesh.point_data, t,
             args.field, not args.no_mesh, box)
    for ax in axes.ravel()[len(frames):]:
        ax.axis("off")
    fig.suptitle(args.title or "%s: liquid cells (blue), free surface "
                 "(%s, line), mesh" % (os.path.basename(
                     os.path.normpath(args.output_dir)),
                     "level set = 0" if args.field == "level_set"
                     else "%s = 1/2" % args.field), fontsize=10)
    fig.tight_layout()
    out_dir = os.path.dirname(os.path.abspath(args.output))
    os.makedirs(out_dir, exist_ok=True)
    fig.savefig(args.output, dpi=args.dpi)
    print("wrote %s (%d panels: t = %s)" % (args.output, len(frames),
          ", ".join("%.3g" % t for t, _ in frames)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
