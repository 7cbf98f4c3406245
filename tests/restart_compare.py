"""Compare the results of two runs of one scene: the statistics column by
column (all but wall_time and linear_iterations), each within 1e-6 of the
column's largest magnitude (volume_change, a fraction of the initial volume
that is round-off on a corrected run: within 1e-6 of 1, i.e. the volume to
6 digits), or within 1e-12 (ROUND_OFF: a column that is zero by symmetry,
such as centroid_x of a centred ball, holds round-off only, which differs
between numbers of ranks), and the solution.pvd series.
Usage: restart_compare.py DIR_A DIR_B"""
import math
import re
import sys

from vefs_tools import statistics

TOLERANCE = 1e-6
ROUND_OFF = 1e-12
SKIPPED = {"wall_time", "linear_iterations"}


def read_statistics(directory):
    """(column names, rows): the rows as the statistics file has them."""
    table = statistics.read_statistics(directory)
    return list(table), [list(row) for row in zip(*table.values())]


def read_series(directory):
    with open(directory + "/solution.pvd") as f:
        return re.findall(r'timestep="([^"]*)"[^>]*file="([^"]*)"', f.read())


def main(a, b):
    names_a, rows_a = read_statistics(a)
    names_b, rows_b = read_statistics(b)
    print("columns: %s" % ("same" if names_a == names_b else "DIFFER"))
    print("rows: %d and %d" % (len(rows_a), len(rows_b)))
    steps_b = [int(r[0]) for r in rows_b]
    print("steps in order, each once: %s" %
          ("yes" if steps_b == list(range(len(rows_b))) else "NO"))
    n = min(len(rows_a), len(rows_b))
    for c, name in enumerate(names_a):
        if name in SKIPPED:
            continue
        x = [r[c] for r in rows_a[:n]]
        y = [r[c] for r in rows_b[:n]]
        finite = [(u, v) for u, v in zip(x, y)
                  if math.isfinite(u) and math.isfinite(v)]
        nan_same = all(math.isnan(u) == math.isnan(v) for u, v in zip(x, y))
        scale = max([abs(u) for u, _ in finite] + [abs(v) for _, v in finite]
                    + [0.0])
        if name == "volume_change":
            scale = max(scale, 1.0)
        diff = max([abs(u - v) for u, v in finite] + [0.0])
        if nan_same and diff <= max(TOLERANCE * scale, ROUND_OFF):
            print("%s: same to %g" % (name, TOLERANCE))
        else:
            print("%s: DIFFERS, largest difference %.3g (largest value %.3g)"
                  % (name, diff, scale))
    series_a, series_b = read_series(a), read_series(b)
    print("solution.pvd: %d files, %s" %
          (len(series_b), "same" if series_a == series_b else "DIFFERENT"))


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
