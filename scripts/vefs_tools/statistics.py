"""The ``statistics`` file of a vefs run, and the few operations on its
columns that several analyses need (standard library only, so that the
test checkers can use it).

read_statistics(path_or_dir)
    Reads the ``statistics`` file a vefs run writes into its output
    directory.  Lines starting with '#' are comments; the last comment line
    before the first data row holds the column names.  Returns a dict
    column name -> list of floats (one entry per data row).

read_csv_reference(path)
    Reads a reference CSV file (data/*.csv: comment lines start with '#',
    then a header row, then comma separated numbers).  Returns a dict
    column -> floats.

interpolate(ts, ys, t)
    Piecewise linear interpolation of ys(ts) at t; None outside [ts[0], ts[-1]].

largest_difference(run, reference, name)
    Largest |run[name] - reference[name]| over the rows of run with t > 0,
    the reference interpolated in time: a time-step study's error against a
    run with a much shorter step.

halving_order(what, errors, minimum)
    Print the observed order log2(e1/e2) of the errors at tau and tau/2 and
    whether it reaches minimum (the test checkers' verdict lines).

parabolic_vertex(p0, p1, p2)
    (t, y) of the vertex of the parabola through three samples (t, y).

zero_crossings(ts, ys)
    Times where ys(ts) changes sign, by linear interpolation between rows.

height_and_depth_unit(statistics)
    The column of the centroid's height and the unit suffix of 2D
    quantities: ("centroid_z", "") for a 3D run, ("centroid_y", "/m") in 2D.

``python3 -m vefs_tools.statistics DIR...`` (from scripts/) lists the
columns of runs.
"""

import bisect
import math
import os

__all__ = ["read_statistics", "read_csv_reference", "interpolate",
           "column", "statistics_path", "parabolic_vertex", "zero_crossings",
           "largest_difference", "halving_order", "height_and_depth_unit"]


def statistics_path(path_or_dir):
    """Path of the statistics file given the file itself or its directory."""
    if os.path.isdir(path_or_dir):
        return os.path.join(path_or_dir, "statistics")
    return path_or_dir


def read_statistics(path_or_dir):
    """Read a vefs ``statistics`` file into {column name: [floats]}.

    The column names are taken from the last comment line before the first
    data row.  Comment lines after the first data row are ignored.  A last
    row with the wrong number of fields (a run still writing the file) is
    dropped; a wrong row anywhere else raises ValueError.
    """
    path = statistics_path(path_or_dir)
    with open(path) as f:
        lines = f.read().splitlines()

    names = None
    last_comment = None
    rows = []
    # (line number, fields) of data lines, to report errors precisely
    data = []
    for number, line in enumerate(lines, start=1):
        stripped = line.strip()
        if not stripped:
            continue
        if stripped.startswith("#"):
            if names is None:
                last_comment = stripped[1:]
            continue
        if names is None:
            if last_comment is None or not last_comment.split():
                raise ValueError("%s:%d: data row before any column-name "
                                 "comment line" % (path, number))
            names = last_comment.split()
        data.append((number, stripped.split()))

    if names is None:
        if last_comment is None:
            raise ValueError("%s: no column names and no data" % path)
        names = last_comment.split()

    for i, (number, fields) in enumerate(data):
        if len(fields) != len(names):
            if i == len(data) - 1:
                break  # incomplete last line of a running simulation
            raise ValueError("%s:%d: %d fields, expected %d (%s)"
                             % (path, number, len(fields), len(names),
                                " ".join(names)))
        try:
            rows.append([float(x) for x in fields])
        except ValueError:
            raise ValueError("%s:%d: not a number in: %s"
                             % (path, number, " ".join(fields)))

    result = {name: [] for name in names}
    for row in rows:
        for name, value in zip(names, row):
            result[name].append(value)
    return result


def column(table, name, source="statistics"):
    """table[name] with a readable error message if the column is missing."""
    try:
        return table[name]
    except KeyError:
        raise KeyError("column '%s' not found in %s (columns: %s)"
                       % (name, source, " ".join(table)))


def read_csv_reference(path):
    """Read a comma separated reference file, skipping '#' comment lines.

    The first non-comment, non-empty line is the header.  Returns a dict
    column name -> list of floats.
    """
    header = None
    result = {}
    with open(path) as f:
        for number, line in enumerate(f, start=1):
            stripped = line.strip()
            if not stripped or stripped.startswith("#"):
                continue
            fields = [x.strip() for x in stripped.split(",")]
            if header is None:
                header = fields
                result = {name: [] for name in header}
                continue
            if len(fields) != len(header):
                raise ValueError("%s:%d: %d fields, expected %d"
                                 % (path, number, len(fields), len(header)))
            try:
                values = [float(x) for x in fields]
            except ValueError:
                raise ValueError("%s:%d: not a number in: %s"
                                 % (path, number, stripped))
            for name, value in zip(header, values):
                result[name].append(value)
    if header is None:
        raise ValueError("%s: no header line" % path)
    return result


def interpolate(ts, ys, t):
    """Linear interpolation of the samples (ts, ys) at t.

    ts must be non-decreasing.  Returns None if t lies outside
    [ts[0], ts[-1]] or if there are no samples.
    """
    n = len(ts)
    if n == 0 or t < ts[0] or t > ts[-1]:
        return None
    if n == 1:
        return ys[0]
    i = bisect.bisect_left(ts, t)
    if i == 0:
        return ys[0]
    if ts[i] == t:
        return ys[i]
    t0, t1 = ts[i - 1], ts[i]
    y0, y1 = ys[i - 1], ys[i]
    if t1 == t0:
        return y1
    w = (t - t0) / (t1 - t0)
    return (1.0 - w) * y0 + w * y1


def largest_difference(run, reference, name):
    """Largest |run[name](t) - reference[name](t)| over the rows of run (a
    read_statistics dict) with 0 < t, the reference's column interpolated
    linearly in t; rows beyond the reference's end are skipped."""
    largest = 0.0
    for t, y in zip(run["time"], run[name]):
        y_ref = interpolate(reference["time"], reference[name], t)
        if t > 0 and y_ref is not None:
            largest = max(largest, abs(y - y_ref))
    return largest


def halving_order(what, errors, minimum):
    """Print the observed order p = log2(e1 / e2) of the errors [e1, e2] at
    tau and tau/2 ('observed order of WHAT') and whether p >= minimum;
    'NO' also for an error missing, zero or not finite."""
    ok = all(e is not None and e > 0 and math.isfinite(e) for e in errors)
    order = math.log2(errors[0] / errors[1]) if ok else float("nan")
    print("observed order of %s: %.2g" % (what, order))
    print("order at least %g: %s"
          % (minimum, "yes" if ok and order >= minimum else "NO"))


def parabolic_vertex(p0, p1, p2):
    """(t, y) of the vertex of the parabola through the samples p0, p1, p2
    (pairs (t, y) with t0 < t1 < t2, not necessarily equally spaced).  The
    vertex time is clamped to [t0, t2] (it lies inside when p1 is a local
    extremum of the samples); if the three points are collinear, p1 is
    returned."""
    (t0, y0), (t1, y1), (t2, y2) = p0, p1, p2
    # y = y1 + c1 (t - t1) + c2 (t - t1)^2 through the three points
    d0, d2 = t0 - t1, t2 - t1
    if d0 == 0 or d2 == 0 or d0 == d2:
        return (t1, y1)
    s0, s2 = (y0 - y1) / d0, (y2 - y1) / d2
    c2 = (s2 - s0) / (d2 - d0)
    c1 = s0 - c2 * d0
    if c2 == 0:
        return (t1, y1)
    dt = -c1 / (2.0 * c2)
    dt = min(max(dt, d0), d2)
    return (t1 + dt, y1 + c1 * dt + c2 * dt * dt)


def zero_crossings(ts, ys):
    """Times where the samples ys(ts) change sign, by linear interpolation
    between the two rows around each change, as (t, direction) with
    direction +1 (upward) or -1 (downward).  A sample that is exactly 0
    counts as a crossing only if its neighbours on both sides (the nearest
    non-zero samples) have opposite signs; it is then taken at the
    middle of the run of zero samples."""
    result = []
    last = None  # index of the last non-zero sample
    for i, y in enumerate(ys):
        if y == 0:
            continue
        if last is not None and (ys[last] > 0) != (y > 0):
            if last == i - 1:
                t0, t1, y0, y1 = ts[last], ts[i], ys[last], y
                t = t0 - y0 * (t1 - t0) / (y1 - y0)
            else:
                t = 0.5 * (ts[last + 1] + ts[i - 1])
            result.append((t, 1 if y > 0 else -1))
        last = i
    return result



def height_and_depth_unit(statistics):
    """("centroid_z", "") for a 3D run, ("centroid_y", "/m") in 2D, where
    forces and energies are per metre of depth."""
    if "centroid_z" in statistics:
        return "centroid_z", ""
    return "centroid_y", "/m"


if __name__ == "__main__":
    import sys
    for p in sys.argv[1:]:
        table = read_statistics(p)
        n = len(next(iter(table.values()))) if table else 0
        print("%s: %d rows, columns: %s" % (statistics_path(p), n,
                                            " ".join(table)))
