"""Checker of oscillating_beam_2d: the seed's soft beam (G = 20 Pa), held by
the no-slip wall x = -0.2, slumps under its own weight, touches the floor
and comes to rest.

References, exact for the continuous problem: B = F F^T positive definite;
the volume kept (bound 1e-6, global correction on); no liquid below the
floor (lowest point of the liquid >= 0); the clamp holds (the liquid
touches the wall x- at every step). Expected of the scheme, not exact: the
motion dies out (kinetic energy over the last 0.1 s below a tenth of its
peak, max |u| below a quarter of its peak): the elastic solid itself does
not dissipate, the first-order scheme and the inelastic contact do.
Exact: no energy is created (no inflow, gravity is in the potential
energy), so the total energy never exceeds its initial value; the scheme
may gain a little, bound 5 %. (Before the stress update dropped the trace
of the velocity gradient, the stress at the wall's top corner grew without
bound and the total energy reached 2.2 times its initial value.)
Printed with 2 significant digits: first contact time, lowest centroid
height, largest kinetic energy."""
import sys

from vefs_tools.statistics import read_statistics
from vefs_tools.prm import read_parameters

s = read_statistics(sys.argv[1])
t, F, kinetic = s["time"], s["contact_force"], s["kinetic_energy"]
n = len(t)
wall = float(read_parameters(sys.argv[1])["Cavity/Lower corner"].split(",")[0])
first = next(i for i in range(n) if F[i] > 0)
print("first contact with a contact wall at t = %.2g s" % t[first])
print("lowest centroid height %.2g m (initial 0.15)" % min(s["centroid_y"]))
print("B positive definite at every step: %s"
      % ("yes" if min(s["min_conformation_eigenvalue"]) > 0 else "NO"))
print("max |volume change| below 1e-6: %s"
      % ("yes" if max(abs(v) for v in s["volume_change"]) < 1e-6 else "NO"))
print("no liquid below the floor: %s" % ("yes" if min(s["lower_y"]) >= 0 else "NO"))
print("held by the wall x- at every step: %s"
      % ("yes" if all(x <= wall + 1e-9 for x in s["lower_x"]) else "NO"))
total = s["total_energy"]
print("total energy at most 5 %% above its initial value at every step: %s"
      % ("yes" if max(total) <= 1.05 * total[0] else "NO"))
peak = max(kinetic)
late = max(k for k, time in zip(kinetic, t) if time >= t[-1] - 0.1)
print("kinetic energy: largest %.2g J/m; over the last 0.1 s below a tenth "
      "of it (at rest): %s" % (peak, "yes" if late < 0.1 * peak else "NO"))
# max_velocity: the largest speed at the vertices of the cells with liquid
# (outside vertices of cut cells included).
speed = s["max_velocity"]
late_speed = max(u for u, time in zip(speed, t) if time >= t[-1] - 0.1)
print("max |u| over the last 0.1 s below a quarter of its largest value "
      "(decays): %s" % ("yes" if late_speed < 0.25 * max(speed) else "NO"))
