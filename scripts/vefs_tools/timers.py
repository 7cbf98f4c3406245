"""The TimerOutput summary that vefs prints at the end of a run (deal.II's
table of wall times by section), read from a run's log, so that the
benchmarks can say where the time went.
"""

import re

_TIMER_ROW = re.compile(r"^\|\s*(.+?)\s*\|\s*(\d+)\s*\|\s*([0-9.eE+-]+)s\s*\|")
_TOTAL = re.compile(r"Total wallclock time elapsed since start\s*\|\s*"
                    r"([0-9.eE+-]+)s")


def read_timer(log_file):
    """(total wall time, {section: (calls, seconds)}) of the last timer
    table in a vefs log; ValueError if there is none."""
    total = None
    sections = {}
    with open(log_file) as f:
        lines = f.read().splitlines()
    for line in lines:
        m = _TOTAL.search(line)
        if m:
            total = float(m.group(1))
            sections = {}
            continue
        m = _TIMER_ROW.match(line)
        if m and total is not None and m.group(1) != "Section":
            sections[m.group(1)] = (int(m.group(2)), float(m.group(3)))
    if total is None:
        raise ValueError("no timer table in %s" % log_file)
    return total, sections


def timer_seconds(log_file):
    """{section: wall seconds, 'total': ...} of the last timer table, {} if
    the log cannot be read or has none (a run that failed): the form the
    transport study keeps in its result files."""
    try:
        total, sections = read_timer(log_file)
    except (OSError, ValueError):
        return {}
    out = {name: seconds for name, (_, seconds) in sections.items()}
    out["total"] = total
    return out
