"""Standing shear wave of an incompressible neo-Hookean solid: the exact
solution and the analysis of a vefs run (the elastic limit of the
Oldroyd-B model, Material/Alpha = 0, sigma = G (B - I), G = eta_p / lambda).

Usage:
  shear_wave.py OUTPUT_DIR [--bound 0.02]     (prints the report of a run)

Scene: cavity [x0,x1] x [y0,y1], periodic in x, filled with the solid,
u(0) = A sin(k (y - y0)) e_x, sigma(0) = 0, no gravity; either periodic in
y with k = 2 pi / L_y (L_y = y1 - y0), or with no-slip walls y0 and y1
(u = 0 there at all times) and k = pi / L_y (half a wavelength). Exact solution, at any amplitude:

    u = A sin(k (y - y0)) cos(w t) e_x,   w = k c,   c = sqrt(G / rho).

Why it is exact at any amplitude: in simple shear the particle at (X, Y)
moves to (X + s(Y,t), Y), so y = Y, F = [[1, s_y], [0, 1]],
B = F F^T = [[1 + s_y^2, s_y], [s_y, 1]]: sigma_xy = G s_y,
sigma_xx = G s_y^2, sigma_yy = 0 (the pressure is constant). None of them
depends on x and u = s_t e_x depends on y only, so (u.grad) u = 0 and the
x momentum balance is rho s_tt = d/dy sigma_xy = G s_yy: the linear wave
equation (the y balance only fixes the constant pressure). With s(y,0) = 0
and s_t(y,0) = A sin(k (y - y0)): s = (A/w) sin(k (y - y0)) sin(w t).
The shear strain amplitude is gamma = max s_y = A k / w = A / c, the
kinetic plus elastic energy (rho/2 |u|^2 + G/2 tr(B - I) = rho/2 u^2 +
G/2 s_y^2) is constant, rho A^2 |Omega| / 4.

Analysis of a run (analyse_run; statistics columns time, probe_u_x,
kinetic_energy, elastic_energy; parameters.prm entries Material/Density,
Polymer viscosity, Relaxation time, Alpha, Cavity/Lower corner, Upper
corner, Postprocess/Probe point):
  * A = probe_u_x(t = 0) / sin(k (y_probe - y0)) (the probe should sit
    where the sine is 1; |sin| < 0.1 is refused);
  * angular frequency: the zero crossings c_0 < ... < c_m of probe_u_x
    (linear interpolation between rows; they alternate in direction), the
    m full half periods between them give the period 2 (c_m - c_0) / m;
    w_sim = 2 pi / period; the frequency error is (w_sim - w) / w (signed;
    needs m >= 1);
  * amplitude: the extremum of every full half period (between c_j and
    c_j+1: the value at the vertex of the parabola through the sample of
    largest |probe_u_x| and its two neighbours) and the initial value
    probe_u_x(0) (the exact solution is even in t, so t = 0 is an
    extremum), e_0, ..., e_m, m half periods apart; the amplitude ratio per
    period is the geometric mean (|e_m| / |e_0|)^(2/m) of the successive
    ratios, the amplitude loss per period 1 - ratio;
  * energy ratio (kinetic_energy + elastic_energy) at the last row over
    the first;
  * periods simulated: t_end w / (2 pi).
The report prints gamma with 2, the frequency error with 3 and the loss and
the energy ratio with 2 significant digits, and "frequency error below
<bound>: yes/NO" (|error| <= bound, default 0.02).
"""

import argparse
import math
import sys

from .statistics import read_statistics, column, parabolic_vertex, zero_crossings
from .prm import read_parameters, parameter, parameter_float, parameter_floats

__all__ = ["exact_velocity", "run_parameters", "frequency",
           "half_period_extrema", "amplitude_ratio_per_period",
           "analyse_run", "format_report", "DEFAULT_BOUND"]

DEFAULT_BOUND = 0.02
MIN_PROBE_FACTOR = 0.1


def exact_velocity(y, t, A, k, w, y0=0.0):
    """x velocity of the standing wave, A sin(k (y - y0)) cos(w t)."""
    return A * math.sin(k * (y - y0)) * math.cos(w * t)


def run_parameters(output_dir):
    """Material, wave number and probe of a run from its parameters.prm:
    dict with rho, eta_p, lam, alpha, G, c, y0, L_y, k, w, probe,
    probe_factor = sin(k (y_probe - y0))."""
    prm = read_parameters(output_dir)
    rho = parameter_float(prm, "Material/Density")
    eta_p = parameter_float(prm, "Material/Polymer viscosity")
    lam = parameter_float(prm, "Material/Relaxation time")
    alpha = parameter_float(prm, "Material/Alpha")
    lower = parameter_floats(prm, "Cavity/Lower corner")
    upper = parameter_floats(prm, "Cavity/Upper corner")
    probe = parameter_floats(prm, "Postprocess/Probe point")
    y_walls = (parameter(prm, "Walls/y-"), parameter(prm, "Walls/y+"))
    if y_walls not in (("periodic", "periodic"), ("no-slip", "no-slip")):
        raise ValueError("the shear wave needs y walls both periodic or both "
                         "no-slip, got %s, %s" % y_walls)
    if not (rho > 0 and eta_p > 0 and lam > 0):
        raise ValueError("the shear wave needs Density, Polymer viscosity "
                         "and Relaxation time > 0 (got rho = %g, eta_p = %g, "
                         "lambda = %g)" % (rho, eta_p, lam))
    if len(lower) < 2 or len(upper) < 2 or len(probe) < 2:
        raise ValueError("Cavity corners and Probe point need at least 2 "
                         "components")
    L_y = upper[1] - lower[1]
    if not L_y > 0:
        raise ValueError("Cavity: the upper corner must lie above the lower "
                         "one in y")
    G = eta_p / lam
    c = math.sqrt(G / rho)
    k = (2.0 if y_walls[0] == "periodic" else 1.0) * math.pi / L_y
    return {"rho": rho, "eta_p": eta_p, "lam": lam, "alpha": alpha, "G": G,
            "c": c, "y0": lower[1], "L_y": L_y, "k": k, "w": k * c,
            "probe": probe,
            "probe_factor": math.sin(k * (probe[1] - lower[1]))}


def frequency(ts, us):
    """(w_sim, crossings) from the zero crossings of us(ts): w_sim =
    pi m / (c_m - c_0) over the m full half periods between the first and
    the last crossing (None if there are fewer than 2 crossings)."""
    crossings = [t for t, _ in zero_crossings(ts, us)]
    if len(crossings) < 2 or crossings[-1] <= crossings[0]:
        return None, crossings
    m = len(crossings) - 1
    return math.pi * m / (crossings[-1] - crossings[0]), crossings


def half_period_extrema(ts, us, crossings):
    """[(t, u)] of the initial sample and of the extremum of every full
    half period between successive crossings (parabola through the sample
    of largest |u| and its neighbours)."""
    extrema = [(ts[0], us[0])]
    for c0, c1 in zip(crossings[:-1], crossings[1:]):
        inside = [i for i, t in enumerate(ts) if c0 < t < c1]
        if not inside:
            continue
        i = max(inside, key=lambda j: abs(us[j]))
        if 0 < i < len(ts) - 1:
            extrema.append(parabolic_vertex((ts[i - 1], us[i - 1]),
                                            (ts[i], us[i]),
                                            (ts[i + 1], us[i + 1])))
        else:
            extrema.append((ts[i], us[i]))
    return extrema


def amplitude_ratio_per_period(extrema):
    """Geometric mean of the ratios of successive |extrema| (half a period
    apart), per period: (|e_m| / |e_0|)^(2/m); None with fewer than 2
    extrema or e_0 = 0."""
    if len(extrema) < 2 or extrema[0][1] == 0:
        return None
    m = len(extrema) - 1
    return (abs(extrema[-1][1]) / abs(extrema[0][1])) ** (2.0 / m)


def analyse_run(output_dir):
    """All shear-wave measures of a run as a dict (run_parameters plus A,
    gamma, t_end, periods, w_sim, frequency_error, crossings, extrema,
    ratio_per_period, loss_per_period, energy_ratio; None where a measure
    is not available)."""
    p = run_parameters(output_dir)
    if abs(p["probe_factor"]) < MIN_PROBE_FACTOR:
        raise ValueError("the probe point y = %g is near a node of the wave "
                         "(sin(k (y - y0)) = %.3g); put it where the sine "
                         "is 1, y = y0 + L_y/4"
                         % (p["probe"][1], p["probe_factor"]))
    stats = read_statistics(output_dir)
    ts = column(stats, "time")
    us = column(stats, "probe_u_x")
    if len(ts) < 2:
        raise ValueError("fewer than 2 data rows in the statistics of %s"
                         % output_dir)
    A = us[0] / p["probe_factor"]
    if all(math.isfinite(u) for u in us):
        w_sim, crossings = frequency(ts, us)
    else:
        w_sim, crossings = None, []  # a run that blew up: not measurable
    extrema = half_period_extrema(ts, us, crossings) if w_sim else []
    ratio = amplitude_ratio_per_period(extrema)
    energy_ratio = None
    if "kinetic_energy" in stats and "elastic_energy" in stats:
        e0 = stats["kinetic_energy"][0] + stats["elastic_energy"][0]
        e1 = stats["kinetic_energy"][-1] + stats["elastic_energy"][-1]
        energy_ratio = e1 / e0 if e0 != 0 else None
    return dict(p, A=A, gamma=abs(A) / p["c"], t_end=ts[-1],
                periods=(ts[-1] - ts[0]) * p["w"] / (2.0 * math.pi),
                w_sim=w_sim,
                frequency_error=(w_sim - p["w"]) / p["w"] if w_sim else None,
                crossings=crossings, extrema=extrema,
                ratio_per_period=ratio,
                loss_per_period=None if ratio is None else 1.0 - ratio,
                energy_ratio=energy_ratio)


def _g(fmt, x):
    return "n/a" if x is None else fmt % x


def format_report(r, bound=DEFAULT_BOUND, loss_bound=None):
    """Report lines for numdiff: few significant digits, no wall times.
    With loss_bound, also a verdict on the amplitude loss per period (the
    exact solution has none)."""
    ok = r["frequency_error"] is not None and \
        abs(r["frequency_error"]) <= bound
    verdicts = []
    if loss_bound is not None:
        loss_ok = r["loss_per_period"] is not None and \
            abs(r["loss_per_period"]) <= loss_bound
        verdicts.append("amplitude loss per period below %g: %s"
                        % (loss_bound, "yes" if loss_ok else "NO"))
    return [
        "elastic limit (Alpha = 0): %s" % ("yes" if r["alpha"] == 0
                                           else "NO"),
        "exact angular frequency w = k sqrt(G/rho): %.3g" % r["w"],
        "shear strain amplitude gamma = A / sqrt(G/rho): %.2g" % r["gamma"],
        "periods simulated: %.3g" % r["periods"],
        "full half periods measured: %d" % max(len(r["crossings"]) - 1, 0),
        "frequency error (w_sim - w) / w: %s"
        % _g("%.3g", r["frequency_error"]),
        "amplitude loss per period: %s" % _g("%.2g", r["loss_per_period"]),
        "energy ratio (kinetic + elastic) end / start: %s"
        % _g("%.2g", r["energy_ratio"]),
        "frequency error below %g: %s" % (bound, "yes" if ok else "NO"),
    ] + verdicts


def main(argv=None, prog=None):
    p = argparse.ArgumentParser(
        prog=prog, description="Standing shear wave of a neo-Hookean solid: "
        "frequency and amplitude of a vefs run against the exact solution.")
    p.add_argument("output_dir", help="vefs output directory (statistics "
                   "and parameters.prm)")
    p.add_argument("--bound", type=float, default=DEFAULT_BOUND,
                   help="bound of |frequency error| for the pass line "
                   "(default %(default)s)")
    p.add_argument("--loss-bound", type=float, default=None,
                   help="if given, also a pass line for |amplitude loss per "
                   "period| below this bound")
    args = p.parse_args(argv)
    try:
        r = analyse_run(args.output_dir)
    except (OSError, ValueError, KeyError) as e:
        message = e.args[0] if isinstance(e, KeyError) and e.args else e
        print("%s: error: %s" % (p.prog, message), file=sys.stderr)
        return 1
    for line in format_report(r, args.bound, args.loss_bound):
        print(line)
    return 0
