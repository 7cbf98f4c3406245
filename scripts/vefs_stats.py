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

read_parameters(path_or_dir)
    Reads the ``parameters.prm`` a vefs run writes into its output directory
    (deal.II ParameterHandler PRM format; any input prm file works too).
    Returns a dict 'Subsection/Entry' -> value string ('Entry' at the top
    level, 'A/B/Entry' for nested subsections).  parameter(), parameter_float()
    and parameter_floats() get one entry with a readable error message.

parabolic_vertex(p0, p1, p2)
    (t, y) of the vertex of the parabola through three samples (t, y).

zero_crossings(ts, ys)
    Times where ys(ts) changes sign, by linear interpolation between rows.
"""

import bisect
import os

__all__ = ["read_statistics", "read_csv_reference", "interpolate",
           "column", "statistics_path", "parameters_path", "read_parameters",
           "parameter", "parameter_float", "parameter_floats",
           "prm_split_comment", "prm_logical_lines",
           "parabolic_vertex", "zero_crossings"]


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


# --------------------------------------------------------------------------
# parameters.prm
# --------------------------------------------------------------------------

def parameters_path(path_or_dir):
    """Path of parameters.prm given the file itself or its directory."""
    if os.path.isdir(path_or_dir):
        return os.path.join(path_or_dir, "parameters.prm")
    return path_or_dir


def prm_split_comment(line):
    """(code, comment) of a PRM line: the code before its '#' comment (a
    backslash-escaped '\\#' is kept as written) and the comment."""
    out = []
    i = 0
    while i < len(line):
        c = line[i]
        if c == "\\" and i + 1 < len(line) and line[i + 1] == "#":
            out.append("\\#")
            i += 2
            continue
        if c == "#":
            return "".join(out), line[i:]
        out.append(c)
        i += 1
    return "".join(out), ""


def prm_logical_lines(lines):
    """Group physical lines (without line ends) into logical lines joined by a
    trailing backslash.  Yields (first index, last index, code, comment)."""
    i = 0
    n = len(lines)
    while i < n:
        first = i
        code, comment = prm_split_comment(lines[i])
        while code.rstrip().endswith("\\") and i + 1 < n:
            i += 1
            c2, comment2 = prm_split_comment(lines[i])
            code = code.rstrip()[:-1] + " " + c2.strip()
            comment = comment2 or comment
        yield first, i, code, comment
        i += 1


def read_parameters(path_or_dir):
    """Read a deal.II ParameterHandler file in PRM format into a dict
    'Subsection/Entry' -> value (a string, surrounding blanks removed).

    Understands what ParameterHandler::print_parameters(..., PRM) writes and
    what it reads: '#' comments ('\\#' is a literal '#'), lines continued
    by a trailing backslash, 'subsection NAME' ... 'end' (nested), and
    'set NAME = VALUE' (split at the first '=').  Runs of blanks in
    subsection and entry names are reduced to one; names are kept as
    written otherwise (case-sensitive, like deal.II).  A later 'set' of the
    same entry wins.  'include' lines are not followed.  Raises ValueError
    with the line number on anything else (unbalanced 'end', a line that
    is none of the above, an unclosed subsection)."""
    path = parameters_path(path_or_dir)
    with open(path) as f:
        physical = f.read().splitlines()

    result = {}
    stack = []
    for first, _, code, _ in prm_logical_lines(physical):
        number = first + 1
        line = code.replace("\\#", "#")
        text = line.strip()
        if not text:
            continue
        words = text.split(None, 1)
        keyword = words[0].lower()
        if keyword == "subsection":
            if len(words) < 2:
                raise ValueError("%s:%d: 'subsection' without a name"
                                 % (path, number))
            stack.append(" ".join(words[1].split()))
        elif keyword == "end" and len(words) == 1:
            if not stack:
                raise ValueError("%s:%d: 'end' without a subsection"
                                 % (path, number))
            stack.pop()
        elif keyword == "set":
            rest = words[1] if len(words) > 1 else ""
            if "=" not in rest:
                raise ValueError("%s:%d: 'set' without '=': %s"
                                 % (path, number, text))
            name, value = rest.split("=", 1)
            name = " ".join(name.split())
            if not name:
                raise ValueError("%s:%d: 'set' without a name"
                                 % (path, number))
            result["/".join(stack + [name])] = value.strip()
        elif keyword == "include":
            continue
        else:
            raise ValueError("%s:%d: not a PRM line: %s" % (path, number,
                                                            text))
    if stack:
        raise ValueError("%s: subsection '%s' not closed by 'end'"
                         % (path, "/".join(stack)))
    return result


def parameter(prm, key, source="parameters.prm"):
    """prm[key] with a readable error message if the entry is missing."""
    try:
        return prm[key]
    except KeyError:
        raise KeyError("entry '%s' not found in %s" % (key, source))


def parameter_float(prm, key, source="parameters.prm"):
    """The entry key as a float (ValueError if it is not a number)."""
    value = parameter(prm, key, source)
    try:
        return float(value)
    except ValueError:
        raise ValueError("entry '%s' in %s is not a number: '%s'"
                         % (key, source, value))


def parameter_floats(prm, key, source="parameters.prm"):
    """The entry key as a list of floats: a comma separated list (as
    Gravity, the cavity corners or the probe point), or [] if empty."""
    value = parameter(prm, key, source)
    if not value.strip():
        return []
    try:
        return [float(x) for x in value.split(",")]
    except ValueError:
        raise ValueError("entry '%s' in %s is not a comma separated list of "
                         "numbers: '%s'" % (key, source, value))


if __name__ == "__main__":
    import sys
    for p in sys.argv[1:]:
        table = read_statistics(p)
        n = len(next(iter(table.values()))) if table else 0
        print("%s: %d rows, columns: %s" % (statistics_path(p), n,
                                            " ".join(table)))
