"""The events of a body that falls on a contact floor and bounces, read from
a vefs statistics file: first contact, lowest centroid, lift-off (contact
force back to zero) and the liquid's mean velocity there, rebound apex, the
energy the first contact removes, the floor's impulse over the first
contact and in each of its steps against Newton's second law for the
centroid, energy left.

Used by tests/bouncing_ball_2d_stiff.py and benchmarks/bouncing_ball_study.py.
"""
from .statistics import read_statistics
from .prm import read_parameters, parameter_float

G = 9.81


def bounce_events(directory):
    """A dict of the events (times in s, heights in m, forces in N/m); the
    lift-off entries are None if the body never leaves the floor."""
    s = read_statistics(directory)
    rho = parameter_float(read_parameters(directory), "Material/Density")
    t, y, F = s["time"], s["centroid_y"], s["contact_force"]
    v_mean = s["centroid_velocity_y"]
    n = len(t)
    m = rho * s["volume"][0]
    energy = [k + p + e for k, p, e in zip(s["kinetic_energy"],
                                           s["potential_energy"],
                                           s["elastic_energy"])]

    def velocity(i):
        return (y[i + 1] - y[i - 1]) / (t[i + 1] - t[i - 1])

    first = next(i for i in range(n) if F[i] > 0)
    lowest = min(range(n), key=lambda i: y[i])
    lift = next((i for i in range(first, n) if F[i] == 0), None)
    e = {
        "mass": m,
        "first_contact_time": t[first],
        "lowest_centroid": y[lowest],
        "lowest_centroid_time": t[lowest],
        "largest_contact_force": max(F),
        "max_volume_change": max(abs(v) for v in s["volume_change"]),
        "lift_off_time": None,
    }
    if lift is None:
        return e
    apex = max(range(lowest, n), key=lambda i: y[i])
    v_before = velocity(first - 1)
    contact = range(first, lift + 1)
    # The liquid's momentum is m times its mean velocity: exact, where
    # differences of the centroid are not. Per step: the floor's impulse
    # against m (dv + g tau).
    step_impulse = [F[i] * (t[i] - t[i - 1]) for i in contact]
    step_momentum = [m * (v_mean[i] - v_mean[i - 1] + G * (t[i] - t[i - 1]))
                     for i in contact]
    e.update({
        "lift_off_time": t[lift],
        "apex": y[apex],
        "apex_time": t[apex],
        "velocity_before_contact": v_before,
        "largest_upward_velocity": max(velocity(i) for i in contact),
        "impulse": sum(step_impulse),
        "momentum_change": sum(step_momentum),
        "worst_step_imbalance": max(abs(a - b) for a, b in
                                    zip(step_impulse, step_momentum))
        / max(step_impulse),
        "energy_left": energy[lift] / energy[0],
        "lift_off_velocity": v_mean[lift],
        # What the first contact removes, over the kinetic energy the body
        # brings to the floor (the material has none to dissipate).
        "contact_loss": (energy[first - 1] - energy[lift])
        / s["kinetic_energy"][first - 1],
    })
    return e
