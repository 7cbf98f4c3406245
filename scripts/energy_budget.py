#!/usr/bin/env python3
"""The energy budget of a bouncing run ('Postprocess/Energy budget = true')
by phase, as the table of doc/bouncing_ball.md: each stage's own share of
the energy the scheme added (J, J/m in 2D) in free fall, over the first
contact (to lift-off), in flight and from the second contact on. Phases
end at the last step before the first contact, at lift-off (the contact
force back to zero) and at the last step before the second contact; a body
that never lifts off has two phases, one that never touches none; then the
whole run. Columns a run does not write show "–".

Usage: /usr/bin/python3 scripts/energy_budget.py OUTPUT_DIR
"""
import sys

from vefs_tools.energy_budget import SHARES, energy_budget
from vefs_tools.statistics import read_statistics

HEADINGS = {
    "transport": "transport − ΔP",
    "momentum": "momentum step + ΔP",
    "contact": "of it: contact",
    "stress_update": "stress update",
    "extension": "extension",
}


def phases(s):
    """(name, t_from, t_to) of the phases of the run with statistics @p s."""
    t, force = s["time"], s["contact_force"]
    n = len(t)
    first = next((i for i in range(n) if force[i] > 0), None)
    if first is None:
        return []
    bounds = [("free fall", t[0], t[first - 1])]
    lift = next((i for i in range(first, n) if force[i] == 0), None)
    if lift is None:
        return bounds + [("on the floor", t[first - 1], t[-1])]
    bounds.append(("first contact", t[first - 1], t[lift]))
    second = next((i for i in range(lift, n) if force[i] > 0), None)
    if second is None:
        return bounds + [("flight", t[lift], t[-1])]
    return bounds + [("flight", t[lift], t[second - 1]),
                     ("second contact", t[second - 1], t[-1])]


def main(directory):
    print("| phase | " + " | ".join(HEADINGS[k] for k in SHARES) +
          " | sum: the scheme's |")
    print("|---" * (len(SHARES) + 2) + "|")
    s = read_statistics(directory)
    rows = phases(s)
    rows.append(("whole run", s["time"][0], s["time"][-1]))
    for name, t_from, t_to in rows:
        budget = energy_budget(directory, t_from, t_to, s)
        shares = budget["shares"]
        total = sum(budget[stage] for stage in ["transport", "flow",
                                                "extension"])
        print("| %s (%.3f to %.3f s) | " % (name, t_from, t_to) +
              " | ".join("–" if shares[k] is None else "%.3g" % shares[k]
                         for k in SHARES) +
              " | %.3g |" % total)


if __name__ == "__main__":
    main(sys.argv[1])
