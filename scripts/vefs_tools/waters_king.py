"""Start-up of planar Poiseuille flow of an Oldroyd-B fluid: the exact
series of Waters & King (1970), and its comparison with a vefs run.

Reference: data/waters_king_1970.md.
Channel -h <= y <= h, fluid at rest at t = 0, constant body force (pressure
gradient) K = -dp/dx switched on at t = 0, no-slip walls; eta0 = eta_s +
eta_p, beta = eta_s / eta0, E = lambda eta0 / (rho h^2), T = t / lambda,
Y = y / h, U = u / U_inf with U_inf = K h^2 / (3 eta0) (the steady mean
velocity; the steady centreline velocity is 1.5):

    U(Y,T) = 1.5 (1 - Y^2)
             - 48 sum_{k>=1} sin(N (1+Y)/2) / N^3 c_N(T),
    c_N(T) = exp(-a T/2) [cosh(b T/2) + (g/b) sinh(b T/2)],
    N = (2k-1) pi,  a = 1 + beta E N^2/4,  b = sqrt(a^2 - E N^2),
    g = 1 - (2 - beta) E N^2/4.

b is imaginary for the low modes when E is large, so everything is complex
(principal square root, Re b >= 0). c_N is evaluated in the overflow-safe
form of the reference,
    c_N = 1/2 [(1 + g/b) e^{r1 T} + (1 - g/b) e^{r2 T}],
    r1 = (b - a)/2 = -E N^2 / (2 (a + b)),  r2 = -(a + b)/2,
where Re r1, Re r2 <= 0 (r1 is written without the cancellation of b - a
for the high modes). When |b T/2| < 1/2 (b near 0, where g/b is large and
the two terms cancel) the direct form with sinh(z)/z is used instead;
b = 0 gives its limit exp(-a T/2) (1 + g T/2).

Number of terms. For beta > 0 the high modes tend to c_N ~ (beta-1)/beta
exp(-T/beta) (the slow root), so the terms fall off like 1/N^3 at any T.
Unless `terms` is given, the sum stops at the first K >= 8 for which the
tail estimate 6 |c|_K / (pi^3 K^2) (|c|_K: a bound of |c_N| at mode K,
assumed not to grow beyond it; 6/(pi^3 K^2) bounds 48 sum_{k>K} 1/N^3) is
below `tol` (default 1e-6), with at most MAX_TERMS = 20000 terms; for
beta > 0 |c|_K is raised to the limit (1-beta)/beta exp(-T/beta) that
|c_N| approaches from below. The estimate is conservative: for E = 1,
beta = 1/9 the sum uses about 1240 terms for T <= 0.01, 794 at T = 0.1,
506 at T = 0.2, 132 at T = 0.5, 8-14 for T >= 1 (printed by the
self-check), and differs from the 20000-term sum by less than 1e-7.
T = 0 returns U = 0 exactly (the series would sum to the steady profile
minus itself). For small T > 0 the fast modes are not yet damped and the
sum needs about 1250 terms (E = 1, beta = 1/9); U(0,T) = 3 E T to 1e-6
there, as it must before the signal of the walls arrives. For beta = 0
(upper-convected Maxwell) the terms only fall off like 1/N^2 (moving
kinks): the 20000 terms leave an error of a few 1e-6 (measured at E = 1).

Usage:
  waters_king.py                          the self-check below
  waters_king.py OUTPUT_DIR [--bound 0.05] [--t-max 10]
                                          comparison of a run (report below)

Self-check (python3 scripts/waters_king.py): reproduces the check-value
table of the reference (E = 1, beta = 1/9, centreline): every value equal
when rounded to 4 decimals (the table is rounded; the largest deviation,
4.6e-5, is printed); the first overshoot U = 2.5513 (within 5e-5) at
T = 1.221 (within 5e-4); the initial slope U(0,T) = 3 E T (within
1e-5 + 1e-4 T for T <= 0.1); T = 0; the steady limit; no slip at Y = +-1;
and the Newtonian start-up for beta = 1 (also with b = 0), to 1e-6.
Exit status 0 if all hold, 1 otherwise. (When written, the series was also
compared with an independent finite-difference solution of
U_T = E (3 + beta U_YY + S_Y), S_T + S = (1 - beta) U_Y, 200 cells:
agreement to 1e-4 at Y = 0 and 0.5 for T = 0.5 ... 3.)

Run comparison (used by tests/waters_king_2d.py and
benchmarks/viscoelastic_convergence.py): compare_run(output_dir) reads the
statistics (columns time, probe_u_x) and parameters.prm of a vefs run
(Material/Density, Solvent viscosity, Polymer viscosity, Relaxation time;
Gravity; Cavity/Lower corner, Upper corner; Postprocess/Probe point) and
compares probe_u_x / U_inf with U(Y_probe, T) at every statistics row with
0 < T <= t_max (default 10), with K = rho g_x, h = half the y extent of
the cavity, and Y_probe = (y_probe - y_centre) / h. The report
(format_report) prints E and beta, the largest |U_sim - U_exact| / 1.5 over
those rows, the first overshoot (largest U for 0 <= T <= t_max) of the run
(vertex of the parabola through the largest sample and its neighbours) and
of the series (golden-section search), U_sim (linear interpolation in the
statistics) and U_exact at T = 1, 2, 5, 10, with 2-3 significant digits,
and "max error below <bound>: yes/NO" (default bound 0.05; NO also when
the run ends before T = t_max). Exit status 1 only if the run cannot be
read (missing file, column or entry, or values that make no sense).
"""

import argparse
import cmath
import math
import sys

from .statistics import read_statistics, column, interpolate, parabolic_vertex
from .prm import read_parameters, parameter_float, parameter_floats

__all__ = ["WatersKing", "velocity", "centreline", "steady_velocity",
           "first_maximum", "run_parameters", "compare_run",
           "format_report", "CHECK_E", "CHECK_BETA",
           "CHECK_VALUES", "CHECK_OVERSHOOT"]

MAX_TERMS = 20000
MIN_TERMS = 8
DEFAULT_TOL = 1e-6
DEFAULT_BOUND = 0.05
#: the steady centreline velocity U(0, infinity), the scale of the errors
STEADY_CENTRELINE = 1.5

# check values of data/waters_king_1970.md: centreline
# U(0,T) for E = 1, beta = 1/9, and the first overshoot (T, U)
CHECK_E = 1.0
CHECK_BETA = 1.0 / 9.0
CHECK_VALUES = [(0.2, 0.6000), (0.6, 1.7631), (1.0, 2.4662), (1.2, 2.5507),
                (2.0, 2.0580), (3.0, 1.3214), (4.0, 1.3171), (5.0, 1.5237),
                (6.0, 1.5546), (8.0, 1.4849), (10.0, 1.5039)]
CHECK_OVERSHOOT = (1.221, 2.5513)


class WatersKing:
    """The series for fixed E and beta; the per-mode constants are computed
    once and kept (mode k = 1, 2, ... extends the list on demand)."""

    def __init__(self, E, beta, tol=DEFAULT_TOL, max_terms=MAX_TERMS):
        if not E > 0:
            raise ValueError("Waters & King: E must be positive, got %r" % E)
        if not 0 <= beta <= 1:
            raise ValueError("Waters & King: beta must lie in [0, 1], got %r"
                             % beta)
        self.E = float(E)
        self.beta = float(beta)
        self.tol = tol
        self.max_terms = max_terms
        self._modes = []

    def _mode(self, k):
        """Constants of mode k (1-based): (N, a, b, g, r1, r2, A1, A2) with
        c_N(T) = A1 e^{r1 T} + A2 e^{r2 T} (A1, A2 None when b = 0)."""
        while len(self._modes) < k:
            n = (2 * len(self._modes) + 1) * math.pi
            en2 = self.E * n * n
            a = 1.0 + self.beta * en2 / 4.0
            b = cmath.sqrt(complex(a * a - en2))
            g = 1.0 - (2.0 - self.beta) * en2 / 4.0
            r1 = -en2 / (2.0 * (a + b))
            r2 = -(a + b) / 2.0
            if b == 0:
                a1 = a2 = None
            else:
                a1 = 0.5 * (1.0 + g / b)
                a2 = 0.5 * (1.0 - g / b)
            self._modes.append((n, a, b, g, r1, r2, a1, a2))
        return self._modes[k - 1]

    def mode_factor(self, k, T):
        """c_N(T) of mode k and a bound of |c_N(T)| (complex, float)."""
        n, a, b, g, r1, r2, a1, a2 = self._mode(k)
        z = b * T / 2.0
        if a1 is None or abs(z) < 0.5:
            # direct form; cosh and sinh of a small argument do not overflow
            sinhc = cmath.sinh(z) / z if z != 0 else 1.0
            damping = math.exp(-a * T / 2.0)
            c = damping * (cmath.cosh(z) + g * T / 2.0 * sinhc)
            return c, damping * (abs(cmath.cosh(z)) +
                                 abs(g) * T / 2.0 * abs(sinhc))
        e1 = cmath.exp(r1 * T)
        e2 = cmath.exp(r2 * T)
        c = a1 * e1 + a2 * e2
        return c, abs(a1) * abs(e1) + abs(a2) * abs(e2)

    def evaluate(self, Y, T, terms=None):
        """(U(Y,T), number of terms used)."""
        if T < 0:
            raise ValueError("Waters & King: T must be >= 0, got %r" % T)
        if T == 0:
            return 0.0, 0
        total = 0.0
        k = 0
        # |c_N| tends to |1 - beta|/beta exp(-T/beta) from below for beta > 0
        limit = (1.0 - self.beta) / self.beta * math.exp(-T / self.beta) \
            if self.beta > 0 else 0.0
        while True:
            k += 1
            n = self._mode(k)[0]
            c, bound = self.mode_factor(k, T)
            bound = max(bound, limit)
            total += math.sin(n * (1.0 + Y) / 2.0) / n ** 3 * c.real
            if terms is not None:
                if k >= terms:
                    break
                continue
            if k >= self.max_terms:
                break
            if k >= MIN_TERMS and \
                    6.0 * bound / (math.pi ** 3 * k * k) < self.tol:
                break
        return 1.5 * (1.0 - Y * Y) - 48.0 * total, k

    def velocity(self, Y, T, terms=None):
        return self.evaluate(Y, T, terms)[0]

    def centreline(self, T, terms=None):
        return self.evaluate(0.0, T, terms)[0]


_CACHE = {}


def _series(E, beta, tol=DEFAULT_TOL):
    key = (float(E), float(beta), tol)
    if key not in _CACHE:
        _CACHE[key] = WatersKing(E, beta, tol)
    return _CACHE[key]


def velocity(Y, T, E, beta, terms=None, tol=DEFAULT_TOL):
    """U(Y, T) = u / U_inf of Waters & King for elasticity number E and
    viscosity ratio beta; terms = None: as many as the tail estimate needs
    for `tol` (see the module documentation)."""
    return _series(E, beta, tol).velocity(Y, T, terms)


def centreline(T, E, beta, terms=None, tol=DEFAULT_TOL):
    """U(0, T)."""
    return _series(E, beta, tol).velocity(0.0, T, terms)


def steady_velocity(Y):
    """U(Y, infinity) = 1.5 (1 - Y^2)."""
    return 1.5 * (1.0 - Y * Y)


def first_maximum(f, t0, t1, samples=200, xtol=1e-6):
    """(t, f(t)) of the first local maximum of f on [t0, t1]: the first
    sample of a uniform grid that is not below its left neighbour and above
    its right one, refined by golden-section search between the
    neighbours. Without an interior local maximum: the largest sample
    (an end point)."""
    ts = [t0 + (t1 - t0) * i / samples for i in range(samples + 1)]
    fs = [f(t) for t in ts]
    for i in range(1, samples):
        if fs[i] >= fs[i - 1] and fs[i] > fs[i + 1]:
            lo, hi = ts[i - 1], ts[i + 1]
            ratio = (math.sqrt(5.0) - 1.0) / 2.0
            x1 = hi - ratio * (hi - lo)
            x2 = lo + ratio * (hi - lo)
            f1, f2 = f(x1), f(x2)
            while hi - lo > xtol:
                if f1 < f2:
                    lo, x1, f1 = x1, x2, f2
                    x2 = lo + ratio * (hi - lo)
                    f2 = f(x2)
                else:
                    hi, x2, f2 = x2, x1, f1
                    x1 = hi - ratio * (hi - lo)
                    f1 = f(x1)
            t = 0.5 * (lo + hi)
            return t, f(t)
    i = max(range(samples + 1), key=lambda j: fs[j])
    return ts[i], fs[i]


# --------------------------------------------------------------------------
# comparison with a vefs run
# --------------------------------------------------------------------------

def run_parameters(output_dir):
    """Material and geometry of a run from its parameters.prm: dict with
    rho, eta_s, eta_p, eta0, lam, g_x, h, y_centre, probe (list), E, beta,
    K, U_inf, Y_probe. Raises ValueError/KeyError on missing or bad
    entries."""
    prm = read_parameters(output_dir)
    rho = parameter_float(prm, "Material/Density")
    eta_s = parameter_float(prm, "Material/Solvent viscosity")
    eta_p = parameter_float(prm, "Material/Polymer viscosity")
    lam = parameter_float(prm, "Material/Relaxation time")
    gravity = parameter_floats(prm, "Gravity")
    lower = parameter_floats(prm, "Cavity/Lower corner")
    upper = parameter_floats(prm, "Cavity/Upper corner")
    probe = parameter_floats(prm, "Postprocess/Probe point")
    eta0 = eta_s + eta_p
    if not (rho > 0 and eta0 > 0 and lam > 0):
        raise ValueError("Waters & King needs Density, Relaxation time and "
                         "Solvent + Polymer viscosity > 0 (got rho = %g, "
                         "lambda = %g, eta0 = %g)" % (rho, lam, eta0))
    if len(lower) < 2 or len(upper) < 2 or len(probe) < 2 or not gravity:
        raise ValueError("Cavity corners, Probe point and Gravity need at "
                         "least 2 (Gravity 1) components")
    h = (upper[1] - lower[1]) / 2.0
    if not h > 0:
        raise ValueError("Cavity: the upper corner must lie above the lower "
                         "one in y")
    y_centre = (upper[1] + lower[1]) / 2.0
    g_x = gravity[0]
    if g_x == 0:
        raise ValueError("Gravity: the x component (the driving force "
                         "K = rho g_x) is 0")
    K = rho * g_x
    return {
        "rho": rho, "eta_s": eta_s, "eta_p": eta_p, "eta0": eta0,
        "lam": lam, "g_x": g_x, "h": h, "y_centre": y_centre,
        "probe": probe, "K": K,
        "E": lam * eta0 / (rho * h * h),
        "beta": eta_s / eta0,
        "U_inf": K * h * h / (3.0 * eta0),
        "Y_probe": (probe[1] - y_centre) / h,
    }


def compare_run(output_dir, t_max=10.0, sample_times=(1.0, 2.0, 5.0, 10.0),
                tol=DEFAULT_TOL):
    """Compare probe_u_x / U_inf of a run with U(Y_probe, T).

    Returns a dict: the run parameters (see run_parameters), T and U_sim,
    U_exact (lists over the statistics rows with 0 < T <= t_max), max_error
    = max |U_sim - U_exact| / 1.5 over them (None without rows), T_end (the
    last T of the run), sim_peak and exact_peak = (T, U) of the largest U
    for 0 <= T <= t_max (the simulated one refined by the parabola through
    the three samples around the largest sample; the exact one by
    first_maximum on the series, i.e. the first overshoot), and at = list
    of (T, U_sim, U_exact) at sample_times (U_sim interpolated linearly,
    None beyond the run)."""
    p = run_parameters(output_dir)
    stats = read_statistics(output_dir)
    time = column(stats, "time")
    u = column(stats, "probe_u_x")
    if not time:
        raise ValueError("no data rows in the statistics of %s" % output_dir)
    series = _series(p["E"], p["beta"], tol)
    Y = p["Y_probe"]
    T_all = [t / p["lam"] for t in time]
    U_all = [x / p["U_inf"] for x in u]
    T, U_sim, U_exact = [], [], []
    for t, x in zip(T_all, U_all):
        if 0 < t <= t_max * (1 + 1e-12):
            T.append(t)
            U_sim.append(x)
            U_exact.append(series.velocity(Y, t))
    errors = [abs(s - e) / STEADY_CENTRELINE for s, e in zip(U_sim, U_exact)]

    # simulated peak over 0 <= T <= t_max (rows with T = 0 included)
    window = [(t, x) for t, x in zip(T_all, U_all)
              if t <= t_max * (1 + 1e-12) and math.isfinite(x)]
    sim_peak = None
    if window:
        i = max(range(len(window)), key=lambda j: window[j][1])
        if 0 < i < len(window) - 1:
            sim_peak = parabolic_vertex(window[i - 1], window[i],
                                        window[i + 1])
        else:
            sim_peak = window[i]
    t_hi = min(t_max, T_all[-1]) if T_all[-1] > 0 else t_max
    exact_peak = first_maximum(lambda s: series.velocity(Y, s), 0.0, t_hi,
                               samples=max(50, int(40 * t_hi)))
    at = []
    for s in sample_times:
        x = interpolate(T_all, U_all, s)
        at.append((s, x, series.velocity(Y, s)))
    if any(not math.isfinite(e) for e in errors):
        max_error = float("nan")  # a run that blew up: NO, not a number
    else:
        max_error = max(errors) if errors else None
    return dict(p, T=T, U_sim=U_sim, U_exact=U_exact, max_error=max_error,
                T_end=T_all[-1], sim_peak=sim_peak, exact_peak=exact_peak,
                at=at)


# --------------------------------------------------------------------------
# self-check against the reference
# --------------------------------------------------------------------------

def self_check(out=sys.stdout):
    ok = True
    wk = WatersKing(CHECK_E, CHECK_BETA)
    print("Waters & King (1970), centreline U(0,T), E = %g, beta = 1/9"
          % CHECK_E, file=out)
    print("%6s %8s %8s %9s %6s" % ("T", "ref", "series", "deviation",
                                   "terms"), file=out)
    worst = 0.0
    good = True
    for T, ref in CHECK_VALUES:
        U, terms = wk.evaluate(0.0, T)
        worst = max(worst, abs(U - ref))
        good &= "%.4f" % U == "%.4f" % ref
        print("%6.1f %8.4f %8.4f %9.1e %6d" % (T, ref, U, U - ref, terms),
              file=out)
    ok &= good
    print("max deviation from the table: %.1e (the table is rounded to 4 "
          "decimals); all equal to 4 decimals: %s"
          % (worst, "yes" if good else "NO"), file=out)

    T, U = first_maximum(wk.centreline, 0.0, 3.0)
    good = abs(T - CHECK_OVERSHOOT[0]) <= 5e-4 and \
        abs(U - CHECK_OVERSHOOT[1]) <= 5e-5
    ok &= good
    print("first overshoot: U = %.4f at T = %.3f (reference %.4f at %.3f): %s"
          % (U, T, CHECK_OVERSHOOT[1], CHECK_OVERSHOOT[0],
             "yes" if good else "NO"), file=out)

    print("small T (initial slope U(0,T) ~ 3 E T):", file=out)
    for T in (1e-4, 1e-3, 1e-2, 0.1):
        U, terms = wk.evaluate(0.0, T)
        good = abs(U - 3 * CHECK_E * T) <= 1e-5 + 1e-4 * T
        ok &= good
        print("  T = %-6g U = %.6e  3ET = %.6e  terms %5d  %s"
              % (T, U, 3 * CHECK_E * T, terms, "yes" if good else "NO"),
              file=out)
    U0 = wk.centreline(0.0)
    good = U0 == 0.0
    ok &= good
    print("T = 0: U = %g: %s" % (U0, "yes" if good else "NO"), file=out)
    U = wk.velocity(0.5, 200.0)
    good = abs(U - steady_velocity(0.5)) < 1e-9
    ok &= good
    print("steady limit U(0.5, 200) = %.6f (1.5 (1 - Y^2) = %.6f): %s"
          % (U, steady_velocity(0.5), "yes" if good else "NO"), file=out)
    wall = max(abs(wk.velocity(y, T)) for y in (-1.0, 1.0)
               for T in (0.1, 1.0, 5.0))
    good = wall < 1e-6
    ok &= good
    print("no slip at Y = +-1: max |U| = %.1e: %s"
          % (wall, "yes" if good else "NO"), file=out)
    # beta = 1: Newtonian start-up, modes exp(-E N^2 T / 4); with
    # E = 4/pi^2 the first mode has b = 0 (up to round-off)
    n_err = 0.0
    for E in (0.5, 4.0 / math.pi ** 2):
        newton = WatersKing(E, 1.0)
        for T in (0.05, 0.5, 2.0):
            exact = 1.5 - 48 * sum(
                math.sin(n / 2) / n ** 3 * math.exp(-E * n * n * T / 4)
                for n in ((2 * k - 1) * math.pi for k in range(1, 2001)))
            n_err = max(n_err, abs(newton.centreline(T) - exact))
    good = n_err < 1e-6
    ok &= good
    print("beta = 1 (Newtonian start-up, also with b = 0): max deviation "
          "%.1e: %s" % (n_err, "yes" if good else "NO"), file=out)
    print("self-check: %s" % ("passed" if ok else "FAILED"), file=out)
    return ok


# --------------------------------------------------------------------------
# report of a run
# --------------------------------------------------------------------------

def _g(fmt, x):
    return "n/a" if x is None else fmt % x


def format_report(r, bound=DEFAULT_BOUND, t_max=10.0):
    """Report lines of compare_run() for numdiff: 2-3 significant digits,
    no wall times or row counts."""
    # a run that stops before T = t_max has not shown the whole start-up
    ok = r["max_error"] is not None and r["max_error"] <= bound and \
        r["T_end"] >= t_max * (1 - 1e-9)
    lines = [
        "elasticity number E = lambda eta0 / (rho h^2): %.3g" % r["E"],
        "viscosity ratio beta = eta_s / eta0: %.3g" % r["beta"],
        "probe Y = (y - y_centre) / h: %.3g"
        % (r["Y_probe"] if abs(r["Y_probe"]) > 1e-12 else 0.0),
        "compared for 0 < T <= %.3g" % min(t_max, r["T_end"]),
        "max |U_sim - U_exact| / 1.5: %s" % _g("%.2g", r["max_error"]),
    ]
    for label, peak in (("simulated", r["sim_peak"]),
                        ("exact", r["exact_peak"])):
        lines.append("first overshoot, %s: U = %s at T = %s"
                     % (label, _g("%.3g", peak and peak[1]),
                        _g("%.3g", peak and peak[0])))
    for T, sim, exact in r["at"]:
        lines.append("U at T = %g: simulated %s, exact %.3g"
                     % (T, _g("%.3g", sim), exact))
    lines.append("max error below %g: %s" % (bound, "yes" if ok else "NO"))
    return lines


def main(argv=None, prog=None):
    """Without arguments: the self-check. With OUTPUT_DIR: the comparison
    of that run, printed by format_report."""
    argv = sys.argv[1:] if argv is None else argv
    if not argv:
        return 0 if self_check() else 1
    p = argparse.ArgumentParser(
        prog=prog, description="Start-up Poiseuille flow of an Oldroyd-B "
        "fluid: the probe velocity of a vefs run against Waters & King "
        "(1970). Without arguments: the self-check of the series.")
    p.add_argument("output_dir", help="vefs output directory (statistics "
                   "and parameters.prm)")
    p.add_argument("--bound", type=float, default=DEFAULT_BOUND,
                   help="bound of the max error relative to 1.5 for the "
                   "pass line (default %(default)s)")
    p.add_argument("--t-max", type=float, default=10.0,
                   help="compare for 0 < T <= t-max (default %(default)s)")
    args = p.parse_args(argv)
    try:
        r = compare_run(args.output_dir, args.t_max)
    except (OSError, ValueError, KeyError) as e:
        message = e.args[0] if isinstance(e, KeyError) and e.args else e
        print("%s: error: %s" % (p.prog, message), file=sys.stderr)
        return 1
    for line in format_report(r, args.bound, args.t_max):
        print(line)
    return 0
