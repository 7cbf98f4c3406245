"""Small-amplitude standing gravity wave in a tank with slip walls: the
surface height at the x- wall against linear theory (Lamb, Hydrodynamics,
sections 227-229, with the viscous decay of section 348):

    eta(0, t) = d + A cos(omega t) exp(-2 nu k^2 t),
    omega^2   = g k tanh(k d),   k = pi / L,

for the surface d + A cos(pi x / L) at rest at t = 0, tank width L (the x
extent of the cavity), depth d = liquid volume / L, g = |Gravity|,
nu = viscosity / density.

From a vefs run (statistics column wall_height, parameters.prm):
- the period, from the zero crossings of eta - d (least-squares line
  through the crossing times, which follow each other every T/2);
- the amplitude at each extremum (parabola through the three rows around
  it) and the numerical amplitude loss per period: the measured decay per
  period divided by the viscous one.

Usage: standing_wave.py OUTPUT_DIR [--digits N]
Prints the exact and measured period, the relative frequency error, the
amplitude loss per period (numerical part), and the number of periods
measured. Standard library only.
"""
import math
import sys

from .statistics import read_statistics, parabolic_vertex, zero_crossings
from .prm import read_parameters, parameter_float, parameter_floats


def exact_wave(output_dir):
    """(omega, viscous decay rate, depth, initial amplitude) of the scene."""
    s = read_statistics(output_dir)
    prm = read_parameters(output_dir)
    lower = parameter_floats(prm, "Cavity/Lower corner")
    upper = parameter_floats(prm, "Cavity/Upper corner")
    gravity = parameter_floats(prm, "Gravity")
    L = upper[0] - lower[0]
    g = math.sqrt(sum(c * c for c in gravity))
    nu = (parameter_float(prm, "Material/Solvent viscosity")
          / parameter_float(prm, "Material/Density"))
    # The cosine integrates to zero over the tank: volume = L d.
    d = s["volume"][0] / L
    bottom = lower[1]
    k = math.pi / L
    omega = math.sqrt(g * k * math.tanh(k * d))
    decay = 2 * nu * k * k
    amplitude = s["wall_height"][0] - bottom - d
    return omega, decay, bottom + d, amplitude


def measure(output_dir):
    s = read_statistics(output_dir)
    omega, decay, level, amplitude = exact_wave(output_dir)
    t = s["time"]
    eta = [h - level for h in s["wall_height"]]

    crossings = [c[0] for c in zero_crossings(t, eta)]
    if len(crossings) < 2:
        raise SystemExit("standing_wave.py: fewer than two zero crossings")
    # t_j = t_0 + j T/2: least-squares slope.
    n = len(crossings)
    mean_j = (n - 1) / 2
    mean_t = sum(crossings) / n
    slope = (sum((j - mean_j) * (c - mean_t) for j, c in enumerate(crossings))
             / sum((j - mean_j) ** 2 for j in range(n)))
    period = 2 * slope
    exact_period = 2 * math.pi / omega

    # Extrema of eta between crossings (and the start, a maximum).
    extrema = [(0.0, eta[0])]
    for i in range(1, len(eta) - 1):
        if (eta[i] - eta[i - 1]) * (eta[i + 1] - eta[i]) < 0 and \
                abs(eta[i]) > 0.5 * abs(amplitude):
            extrema.append(parabolic_vertex((t[i - 1], eta[i - 1]),
                                            (t[i], eta[i]),
                                            (t[i + 1], eta[i + 1])))
    first, last = extrema[0], extrema[-1]
    periods = (last[0] - first[0]) / exact_period
    loss = None
    if periods > 0.4:
        measured = (abs(last[1]) / abs(first[1])) ** (1 / periods)
        viscous = math.exp(-decay * exact_period)
        loss = 1 - measured / viscous
    return {
        "exact_period": exact_period,
        "period": period,
        "frequency_error": exact_period / period - 1,
        "amplitude_loss_per_period": loss,
        "periods": periods,
        "initial_amplitude": amplitude,
        "viscous_loss_per_period": 1 - math.exp(-decay * exact_period),
    }


def main():
    if len(sys.argv) < 2:
        raise SystemExit(__doc__)
    digits = 2
    if "--digits" in sys.argv:
        digits = int(sys.argv[sys.argv.index("--digits") + 1])
    m = measure(sys.argv[1])
    f = "%." + str(digits) + "g"
    print(("exact period: " + f + " s") % m["exact_period"])
    print(("measured period: " + f + " s") % m["period"])
    print(("frequency error: " + f) % m["frequency_error"])
    print(("initial amplitude: " + f + " m") % m["initial_amplitude"])
    print(("periods measured: %.1f") % m["periods"])
    print(("viscous amplitude loss per period (exact): " + f)
          % m["viscous_loss_per_period"])
    if m["amplitude_loss_per_period"] is not None:
        print(("numerical amplitude loss per period: " + f)
              % m["amplitude_loss_per_period"])
