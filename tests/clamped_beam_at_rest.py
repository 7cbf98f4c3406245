"""Checker of clamped_beam_at_rest: a stiff beam (G = 2000 Pa, rho = 1000,
the cantilever [-0.2, 0.1] x [0.1, 0.2] held by the no-slip wall x = -0.2)
under gravity g = 0.004 m/s^2, released at rest. The material keeps its
energy, so the sum of the energies may not exceed its start by more than
1 % (issue 49), and the centroid oscillates about the static sag. Reference
for that sag: a Timoshenko cantilever in plane strain, incompressible
(E' = 4 G, shear coefficient 5/6) under its weight q = rho g H: mean
deflection q L^4 / (20 E' I) + q L^2 / (3 k G H), I = H^3 / 12, which the
time-averaged sag must match within 10 %."""
import sys

from vefs_tools.statistics import read_statistics

G, rho, g, L, H = 2000.0, 1000.0, 0.004, 0.3, 0.1
q = rho * g * H
static_sag = q * L**4 / (20 * 4 * G * H**3 / 12) + q * L**2 / (3 * 5 / 6 * G * H)

s = read_statistics(sys.argv[1])
t, y, total = s["time"], s["centroid_y"], s["total_energy"]
rise = max(e - total[0] for e in total) / total[0]
sag = sum((t[i + 1] - t[i]) * (2 * y[0] - y[i] - y[i + 1]) / 2
          for i in range(len(t) - 1)) / (t[-1] - t[0])
print("final time: %.4g" % t[-1])
print("largest rise of the energy sum over its start: %.1f %%" % (100 * rise))
print("mean sag of the centroid: %.3g mm (Timoshenko, static: %.3g mm)"
      % (1e3 * sag, 1e3 * static_sag))
ok = rise <= 0.01 and abs(sag / static_sag - 1) <= 0.1
print("energy within 1 %% and sag within 10 %%: %s" % ("ok" if ok else "FAIL"))
sys.exit(0 if ok else 1)
