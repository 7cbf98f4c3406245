"""The energy budget of a run with 'Postprocess/Energy budget = true': what
each stage of the steps added to the total energy (kinetic + potential +
elastic) over an interval of time, and whether the stages account for the
whole change of the total.

Used by tests/bouncing_ball_2d_stiff.py and scripts/energy_budget.py.
"""
from .statistics import read_statistics

STAGES = ["transport", "flow", "extension"]
# Each stage's own share (doc/bouncing_ball.md, "Energy budget"): the body's
# motion changes the potential energy in the transport and gravity works in
# the momentum step, so the potential change moves from the one to the
# other; the stress update and the contact walls' work are parts of the flow
# step, the contact's of the momentum step's.
SHARES = ["transport", "momentum", "contact", "stress_update", "extension"]


def energy_budget(directory, t_from=None, t_to=None):
    """A dict with, over the steps ending in (t_from, t_to]: the sum of each
    stage's column ("transport", "flow", "extension"), "change" (the change
    of the total energy from the row at t_from to the row at t_to),
    "initial" (the total energy of the first row) and "closure" (the largest
    |sum of the stages of a step - change of the total in that step| over
    the interval, the bookkeeping error), "shares" (a dict of each stage's
    own share, SHARES: the transport less the potential change, the
    momentum step with it, of which the contact walls' work, the stress
    update, the extension; None where the run has no such column)."""
    s = read_statistics(directory)
    t = s["time"]
    total = [k + p + e for k, p, e in zip(s["kinetic_energy"],
                                          s["potential_energy"],
                                          s["elastic_energy"])]
    first = 0 if t_from is None else max(i for i in range(len(t))
                                         if t[i] <= t_from)
    last = len(t) - 1 if t_to is None else max(i for i in range(len(t))
                                               if t[i] <= t_to)
    budget = {stage: 0.0 for stage in STAGES}
    closure = 0.0
    for i in range(first + 1, last + 1):
        step = 0.0
        for stage in STAGES:
            change = s["energy_change_" + stage][i]
            budget[stage] += change
            step += change
        closure = max(closure, abs(step - (total[i] - total[i - 1])))
    budget["change"] = total[last] - total[first]
    budget["initial"] = total[0]
    budget["closure"] = closure
    potential = s["potential_energy"][last] - s["potential_energy"][first]

    def part(column):
        return sum(s[column][first + 1:last + 1]) if column in s else None

    stress_update = part("energy_change_stress_update")
    budget["shares"] = {
        "transport": budget["transport"] - potential,
        "momentum": budget["flow"] - (stress_update or 0.0) + potential,
        "contact": part("energy_change_contact"),
        "stress_update": stress_update,
        "extension": budget["extension"],
    }
    return budget
