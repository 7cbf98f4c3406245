#!/usr/bin/env python3
"""The body's shape at selected time steps, as the seed's Figures 1 and 2.

Usage:
  /usr/bin/python3 scripts/render_shapes.py OUTPUT_DIR [--steps 3,6,9]
      [--every N] [--field level_set] [--section y=0 ...] [--overlay]
      [--columns 6] [--out shapes.png]

Reads OUTPUT_DIR/solution.pvd (the list of .pvtu records and their times),
each .pvtu's .vtu pieces (one per MPI rank) and OUTPUT_DIR/statistics (step
numbers and times), with numpy and matplotlib only: the reader
(vefs_tools/vtu.py) knows the files deal.II's DataOut writes (inline
base64, zlib compressed or not, UInt32 or UInt64 headers, or ascii) so
that no VTK installation is needed.

The body is where the level set is negative; its outline is the 0 contour
of ``level_set`` (the transported field, bilinear/trilinear per cell in the
output, so the contour is the one the code sees), or, with
``--field liquid_fraction`` (or ``phi``), the 0.5 contour of that 0/1 field
averaged at the vertices (a coarser, cell-sized outline).

2D: deal.II writes each cell (an axis-aligned quadrilateral here) with its
own 4 vertices; the cells' bilinear fields are sampled on the regular grid
of the smallest cell size (exact at its points, see resample) and
matplotlib's contour draws the outline on that grid (linear along the grid
lines). A triangulation of the cells themselves would have T-junctions at
hanging nodes, which matplotlib's tri* functions do not support. Checked
on the 2D stiff ball: the area inside the outline equals the statistics'
volume within 3e-4 and its centroid the statistics' within 0.02 mm.

3D: a section by an axis-aligned plane, e.g. y = 0 (default: the plane
through the middle of the cavity in y). The cavity's mesh is made of
axis-aligned boxes, and on such a box the Q1 output is trilinear, so on
the plane it is exactly the bilinear interpolant of the values
interpolated linearly along the 4 edges that cross the plane; these
rectangles are then treated as in 2D. Boxes that are not axis-aligned
are refused.

A step is mapped to its time through the statistics file (or the
``Time step`` of parameters.prm when that file is missing) and then to the
output nearest in time; when no output was written at that step the
substitute is printed.
"""
import argparse
import math
import os

import matplotlib
import numpy as np

from vefs_tools.statistics import read_statistics
from vefs_tools.prm import read_parameters
from vefs_tools.vtu import read_pvtu, read_series, cell_rows, plane_data

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


# ------------------------------------------------------ steps and outputs

def step_times(output_dir, last_time):
    """{step: time}, from the statistics, else from a uniform Time step
    up to last_time."""
    if os.path.exists(os.path.join(output_dir, "statistics")):
        s = read_statistics(output_dir)
        return {int(round(n)): t for n, t in zip(s["step"], s["time"])}
    tau = float(read_parameters(output_dir)["Time/Time step"])
    return {n: n * tau for n in range(int(round(last_time / tau)) + 1)}


def output_interval(output_dir):
    """Output/Interval of the run (1 if unknown)."""
    try:
        return max(1, int(read_parameters(output_dir)["Output/Interval"]))
    except (OSError, ValueError, KeyError):
        return 1


def output_time_interval(output_dir):
    """Output/Time interval of the run (0 if unset or unknown)."""
    try:
        return float(read_parameters(output_dir).get("Output/Time interval", 0))
    except (OSError, ValueError):
        return 0.


def parse_steps(text):
    """The --steps option: comma separated step numbers, a:b:c for
    range(a, b + 1, c); None if not given."""
    if not text:
        return None
    steps = []
    for item in text.split(","):
        if ":" in item:
            lo, hi, by = (int(v) for v in item.split(":"))
            steps += range(lo, hi + 1, by)
        else:
            steps.append(int(item))
    return steps


def select_outputs(output_dir, steps, every):
    """[(requested step, step of the output used, its time, .pvtu path)].

    Each step's time (statistics) is matched to the output nearest in time;
    a step without an output is reported with the substitute. Without
    --steps or --every: about 18 outputs (as many as the paper's figures)
    at multiples of the output interval.
    """
    series = read_series(output_dir)
    out_times = np.array([t for t, _ in series])
    times = step_times(output_dir, out_times[-1])
    numbers = np.array(sorted(times))
    values = np.array([times[n] for n in numbers])
    # pvd times have 6 significant digits: same step if within a quarter
    # of the smallest time step
    tolerance = 0.25 * np.diff(values).min() if len(values) > 1 else 1e-12
    if steps is None and every is None and output_time_interval(output_dir) > 0:
        return [(m, m, t, path) for (t, path) in series[1:]
                for m in [int(numbers[np.argmin(abs(values - t))])]]
    if steps is None:
        if every is None:
            interval = output_interval(output_dir)
            every = interval * max(1, int(math.ceil(
                numbers[-1] / (18.0 * interval))))
        steps = list(range(every, numbers[-1] + 1, every))
    chosen = []
    for n in steps:
        if n not in times:
            print("step %d: not in the statistics (the run has not reached "
                  "it); skipped" % n)
            continue
        i = int(np.argmin(abs(out_times - times[n])))
        m = int(numbers[np.argmin(abs(values - out_times[i]))])
        if abs(out_times[i] - times[n]) > tolerance:
            print("step %d (t = %g): no output; using the nearest, step %d "
                  "(t = %g)" % (n, times[n], m, out_times[i]))
        chosen.append((n, m, out_times[i], series[i][1]))
    return chosen


# ---------------------------------------------------------- geometry

def body_function(values, field):
    """A function negative inside the body: the level set itself, or
    0.5 - fraction for the 0/1 fields (phi, liquid_fraction)."""
    return values if field == "level_set" else 0.5 - values


# ---------------------------------------------------------- drawing

WALL_NAMES = "xyz"


def wall_styles(output_dir, dim):
    """{'x-': wall type, ...} from parameters.prm (empty if unreadable)."""
    try:
        prm = read_parameters(output_dir)
    except (OSError, ValueError):
        return {}
    sides = ["%s%s" % (WALL_NAMES[d], s) for d in range(dim) for s in "-+"]
    return {side: prm.get("Walls/" + side, "") for side in sides}


def draw_walls(ax, box, dims, walls):
    """The cavity's sides in the panel: solid where there is a wall (thick
    for a contact wall), dotted where it is open."""
    (x0, x1), (y0, y1) = box
    sides = {(dims[0], "-"): ([x0, x0], [y0, y1]),
             (dims[0], "+"): ([x1, x1], [y0, y1]),
             (dims[1], "-"): ([x0, x1], [y0, y0]),
             (dims[1], "+"): ([x0, x1], [y1, y1])}
    for (d, s), (xs, ys) in sides.items():
        kind = walls.get("%s%s" % (WALL_NAMES[d], s), "")
        if kind in ("", "open"):
            ax.plot(xs, ys, ":", color="0.5", lw=0.8)
        else:
            ax.plot(xs, ys, "-", color="k", lw=1.6 if kind == "contact" else 1)


def draw_body(ax, grid, color="C0", fill=True):
    """The region g < 0 lightly filled and its outline g = 0."""
    if grid is None or grid[2].min() >= 0:
        return False
    x, y, g = grid
    if fill:
        ax.contourf(x, y, g, levels=[g.min() - 1, 0], colors=[color],
                    alpha=0.25)
    ax.contour(x, y, g, levels=[0], colors=[color], linewidths=1.2)
    return True


def parse_section(text):
    """'y=0' -> (1, 0.0)."""
    name, value = text.replace(" ", "").split("=")
    return WALL_NAMES.index(name.lower()), float(value)


def render(output_dir, frames, field, dim, sections, columns, overlay, png):
    """Small multiples (one panel per frame and section), or one panel per
    section with all outlines coloured by time (--overlay)."""
    walls = wall_styles(output_dir, dim)
    planes = [(None, None)] if dim == 2 else sections
    data = []   # per frame: [(grid, box, dims) per plane]
    for n, m, t_out, path in frames:
        mesh = read_pvtu(path, [field])
        points, cells, types, values, pieces = (
            mesh.points, cell_rows(mesh), mesh.types, mesh.point_data,
            mesh.pieces)
        if field not in values:
            raise SystemExit("%s: no point field '%s'" % (path, field))
        g = body_function(values[field].astype(float), field)
        row = []
        for axis, c in planes:
            dims = [0, 1] if dim == 2 else [d for d in range(3) if d != axis]
            box = [(points[:, d].min(), points[:, d].max()) for d in dims]
            row.append((plane_data(points, cells, types, g, dim, axis, c),
                        box, dims))
        data.append(row)
        print("step %d: %s (%d piece%s)" % (m, os.path.basename(path), pieces,
                                            "" if pieces == 1 else "s"))
    box = data[0][0][1] if data else [(0, 1), (0, 1)]
    aspect = (box[1][1] - box[1][0]) / (box[0][1] - box[0][0])
    width = 2.3
    labels = [("" if a is None else "%s = %g" % (WALL_NAMES[a], c))
              for a, c in planes]
    if overlay:
        fig, axes = plt.subplots(1, len(planes), squeeze=False,
                                 constrained_layout=True,
                                 figsize=(5.5 * len(planes), 5 * aspect + 0.8))
        cmap = plt.get_cmap("viridis")
        norm = matplotlib.colors.Normalize(frames[0][2], frames[-1][2])
        for j, ax in enumerate(axes[0]):
            for (n, m, t_out, _), row in zip(frames, data):
                draw_body(ax, row[j][0], cmap(norm(t_out)), fill=False)
            finish_panel(ax, data[0][j][1], data[0][j][2], walls,
                         labels[j] + "  t = %g ... %g s"
                         % (frames[0][2], frames[-1][2]))
        fig.colorbar(matplotlib.cm.ScalarMappable(norm, cmap), ax=axes[0],
                     label="t (s)", shrink=0.8)
    else:
        columns = min(columns, max(1, len(frames)))
        rows_per = int(math.ceil(len(frames) / float(columns)))
        fig, axes = plt.subplots(rows_per * len(planes), columns,
                                 squeeze=False,
                                 figsize=(width * columns,
                                          (width * aspect + 0.45)
                                          * rows_per * len(planes)),
                                 constrained_layout=True)
        for ax in axes.ravel():
            ax.set_axis_off()
        for j in range(len(planes)):
            for i, ((n, m, t_out, _), row) in enumerate(zip(frames, data)):
                ax = axes[j * rows_per + i // columns, i % columns]
                ax.set_axis_on()
                grid, b, dims = row[j]
                if not draw_body(ax, grid):
                    ax.text(0.5, 0.5, "no body here", ha="center",
                            transform=ax.transAxes, fontsize=7)
                title = "step %d, t = %.4g s" % (m, t_out)
                if m != n:
                    title += " (for %d)" % n
                if labels[j]:
                    title += "\n" + labels[j]
                finish_panel(ax, b, dims, walls, title, ticks=False)
    fig.savefig(png, dpi=120)
    print("wrote %s" % png)


def finish_panel(ax, box, dims, walls, title, ticks=True):
    """Walls, equal aspect, limits, title."""
    draw_walls(ax, box, dims, walls)
    pad = 0.02 * (box[0][1] - box[0][0])
    ax.set_xlim(box[0][0] - pad, box[0][1] + pad)
    ax.set_ylim(box[1][0] - pad, box[1][1] + pad)
    ax.set_aspect("equal")
    ax.set_title(title, fontsize=8)
    if ticks:
        ax.set_xlabel(WALL_NAMES[dims[0]] + " (m)")
        ax.set_ylabel(WALL_NAMES[dims[1]] + " (m)")
    else:
        ax.set_xticks([])
        ax.set_yticks([])
        for spine in ax.spines.values():
            spine.set_visible(False)


def dimension(output_dir):
    """The run's dimension, from parameters.prm (default 2)."""
    try:
        return int(read_parameters(output_dir).get("Dimension", "2"))
    except (OSError, ValueError):
        return 2


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("output_dir")
    p.add_argument("--steps", help="comma separated step numbers, e.g. "
                   "3,6,9 (a:b:c for range(a, b + 1, c))")
    p.add_argument("--every", type=int, help="every N-th step")
    p.add_argument("--field", default="level_set",
                   choices=["level_set", "liquid_fraction", "phi"])
    p.add_argument("--section", action="append",
                   help="3D: plane of a section, e.g. y=0 (repeatable; "
                   "default: y through the middle of the cavity)")
    p.add_argument("--columns", type=int, default=6)
    p.add_argument("--overlay", action="store_true",
                   help="all outlines in one panel, coloured by time")
    p.add_argument("--out", default="shapes.png")
    a = p.parse_args(argv)
    steps = parse_steps(a.steps)
    dim = dimension(a.output_dir)
    frames = select_outputs(a.output_dir, steps, a.every)
    if not frames:
        raise SystemExit("no output selected")
    sections = [parse_section(s) for s in a.section or []]
    if dim == 3:
        points = read_pvtu(frames[0][3], []).points
        low, high = points.min(0), points.max(0)
        sections = sections or [(1, 0.5 * (low[1] + high[1]))]
        for axis, c in sections:
            if not low[axis] - 1e-6 <= c <= high[axis] + 1e-6:
                raise SystemExit("section %s = %g is outside the mesh "
                                 "[%g, %g]" % (WALL_NAMES[axis], c,
                                               low[axis], high[axis]))
    render(a.output_dir, frames, a.field, dim, sections, a.columns,
           a.overlay, a.out)


if __name__ == "__main__":
    main()
