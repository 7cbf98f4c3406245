"""Checker of drop_into_pool_2d: the tutorial's drop (radius R = 0.02 m,
centre at y = 0.15 m) falls into a pool 0.05 m deep that fills the box
0.2 m wide; slip walls, water.

References, exact for the continuous problem:
 - The liquid area is 0.2 * 0.05 + pi R^2 = 0.0112566 m^2 (the pool's
   surface lies on mesh lines, so the difference of the initial volume is
   the drop's outline on the mesh); the volume correction keeps it:
   |volume_change| below 1e-9 (5e-14 in free fall, at most 2.4e-10 in
   the splash).
 - Until it touches the pool at t = sqrt(2 * 0.08 / g) = 0.1277 s, the drop
   is in free fall (uniform velocity -g t, no pressure) and the pool at
   rest: the largest speed max_velocity is g t (bound 1e-3), and the top of
   the drop has fallen g t^2 / 2 at t = 0.1 s, which the second-order
   scheme (the default) follows exactly (velocity Verlet; the first-order
   scheme's characteristics use the velocity of the step before and fall
   g tau^2 n (n - 1) / 2, 0.98 mm less).
 - The mean velocity is -(A_drop / V) g t: it measures the drop's area
   A_drop, which the transport on this coarse mesh lets shrink (the
   volume correction moves it to the pool).
 - The contact: the first step whose largest speed departs from g t by
   1 %; on this mesh the drop feels the pool 2-3 cells before it touches.
 - The impact only removes energy (viscous, numerical): the total energy
   at the end is below its value just before the contact.
Printed with 2 significant digits: the relative errors before the contact
(equal on 1 and 2 ranks to 2e-10); with 1 decimal the fraction of the
drop's kinetic energy lost in the impact (0.4571 on 1 rank, 0.4569 on 2)."""
import math
import sys

from vefs_tools.statistics import read_statistics

G = 9.81
R = 0.02
POOL = 0.2 * 0.05
AREA = POOL + math.pi * R * R
T_CHECK = 0.1                     # s, before the contact
T_CONTACT = math.sqrt(2 * 0.08 / G)

s = read_statistics(sys.argv[1])
t, v = s["time"], s["volume"]
n = min(range(len(t)), key=lambda i: abs(t[i] - T_CHECK))

print("initial volume: %.6g (exact pool + drop %.6g), relative difference %.2g"
      % (v[0], AREA, v[0] / AREA - 1))
print("max |volume change| below 1e-9: %s"
      % ("yes" if max(abs(x) for x in s["volume_change"]) < 1e-9 else "NO"))

speed_error = s["max_velocity"][n] / (G * t[n]) - 1
print("t = %g s: drop speed max_velocity / (g t) - 1 below 1e-3: %s"
      % (t[n], "yes" if abs(speed_error) < 1e-3 else "NO (%.2g)" % speed_error))
fall = s["upper_y"][0] - s["upper_y"][n]
print("t = %g s: fall of the drop's top %.3g m, relative error against "
      "g t^2/2: %.2g" % (t[n], fall, fall / (0.5 * G * t[n] ** 2) - 1))
drop_now = -s["centroid_velocity_y"][n] * v[n] / (G * t[n])
print("t = %g s: drop area from the mean velocity / its initial area - 1: %.2g"
      % (t[n], drop_now / (v[0] - POOL) - 1))

# contact: the first step whose largest speed departs from g t by 1 %
contact = next(i for i in range(1, len(t))
               if abs(s["max_velocity"][i] / (G * t[i]) - 1) > 0.01)
print("contact seen at t = %.3g s (free fall: %.4g s)"
      % (t[contact], T_CONTACT))
before = contact - 1
energy = s["total_energy"]
lost = (energy[before] - energy[-1]) / s["kinetic_energy"][before]
print("energy lost from t = %.3g s to the end, in units of the kinetic "
      "energy then: %.1f (%s)" % (t[before], lost,
                                  "a loss" if lost > 0 else "NO, a gain"))
