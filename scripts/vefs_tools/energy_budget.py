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


def step_shares(s):
    """Each stage's own share (SHARES) in every step of the statistics @p s
    (read_statistics()): lists by row, the first row's zero; None for a
    column the run does not write."""
    n = len(s["time"])
    falls = [0.0] + [b - a for a, b in zip(s["potential_energy"],
                                           s["potential_energy"][1:])]

    def column(name):
        return [0.0] + list(s[name][1:]) if name in s else None

    stress_update = column("energy_change_stress_update")
    flow = column("energy_change_flow")
    return {
        "transport": [c - d for c, d in zip(
            column("energy_change_transport"), falls)],
        "momentum": [flow[i] + falls[i] -
                     (stress_update[i] if stress_update else 0.0)
                     for i in range(n)],
        "contact": column("energy_change_contact"),
        "stress_update": stress_update,
        "extension": column("energy_change_extension"),
    }


def energy_budget(directory, t_from=None, t_to=None, statistics=None):
    """A dict with, over the steps ending in (t_from, t_to]: the sum of each
    stage's column ("transport", "flow", "extension"), "change" (the change
    of the total energy from the row at t_from to the row at t_to),
    "initial" (the total energy of the first row) and "closure" (the largest
    |sum of the stages of a step - change of the total in that step| over
    the interval, the bookkeeping error), "shares" (the sums of
    step_shares(); None where the run has no such column). @p statistics:
    the run's, if already read."""
    s = read_statistics(directory) if statistics is None else statistics
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
    budget["shares"] = {
        name: None if share is None else sum(share[first + 1:last + 1])
        for name, share in step_shares(s).items()}
    return budget
