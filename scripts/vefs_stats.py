#!/usr/bin/env python3
"""Helpers to read vefs output (standard library only).

read_statistics(path_or_dir)
    Reads the ``statistics`` file a vefs run writes into its output
    directory.  Lines starting with '#' are comments; the last comment line
    before the first data row holds the column names.  Returns a dict
    column name -> list of floats (one entry per data row).

read_csv_reference(path)
    Reads a reference CSV file (comment lines start with '#', then a header
    row, then comma separated numbers).  Returns a dict column -> floats.

interpolate(ts, ys, t)
    Piecewise linear interpolation of ys(ts) at t; None outside [ts[0], ts[-1]].
"""

import bisect
import os

__all__ = ["read_statistics", "read_csv_reference", "interpolate",
           "column", "statistics_path"]


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


if __name__ == "__main__":
    import sys
    for p in sys.argv[1:]:
        table = read_statistics(p)
        n = len(next(iter(table.values()))) if table else 0
        print("%s: %d rows, columns: %s" % (statistics_path(p), n,
                                            " ".join(table)))
