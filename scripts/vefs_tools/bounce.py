"""The events of a body that falls on a contact floor and bounces, read from
a vefs statistics file: first contact, lowest centroid, lift-off (contact
force back to zero), rebound apex, the floor's impulse over the first
contact against Newton's second law for the centroid, energy left.

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
    v_before, v_after = velocity(first - 1), velocity(lift)
    e.update({
        "lift_off_time": t[lift],
        "apex": y[apex],
        "apex_time": t[apex],
        "velocity_before_contact": v_before,
        "largest_upward_velocity": max(velocity(i)
                                       for i in range(first, lift + 1)),
        "impulse": sum(F[i] * (t[i] - t[i - 1])
                       for i in range(first, lift + 1)),
        # The liquid's momentum is m times its mean velocity: exact, where
        # differences of the centroid are not.
        "momentum_change": m * (v_mean[lift] - v_mean[first - 1])
        + m * G * (t[lift] - t[first - 1]),
        "energy_left": energy[lift] / energy[0],
    })
    return e
