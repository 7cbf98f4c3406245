"""Checker of bouncing_ball_2d_stiff: a stiff neo-Hookean ball (G = 2000 Pa)
falls on a contact floor, bounces and lifts off.

Checked against Newton's second law for the centroid, which holds exactly
for the whole body: with the side walls never touched, the only vertical
forces are gravity and the contact force F of the floor, so
    m (v_c(t2) - v_c(t1)) = int_t1^t2 (F - m g) dt,
with m = rho V and v_c the centroid velocity (finite differences of the
centroid column). Compared over the first contact, from the last step
before it to the first step after lift-off (bound 10%: v_c from
differences of a centroid measured on the level set, and F from the
first-order reaction). Printed with 2-3 significant digits: first contact
and lift-off times, lowest centroid height, rebound apex, contact force
peak, the impulse balance, volume change (bound 1e-6) and the energy
left after the bounce."""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scripts"))
from vefs_stats import read_statistics, read_parameters, parameter_float  # noqa: E402

s = read_statistics(sys.argv[1])
prm = read_parameters(sys.argv[1])
rho = parameter_float(prm, "Material/Density")
g = 9.81
t, y, F = s["time"], s["centroid_y"], s["contact_force"]
m = rho * s["volume"][0]
n = len(t)

first = next(i for i in range(n) if F[i] > 0)
lift = next((i for i in range(first, n) if F[i] == 0), None)
print("first contact at t = %.3g s" % t[first])
lowest = min(range(n), key=lambda i: y[i])
print("lowest centroid height %.3g m at t = %.3g s (initial 0.15)" % (y[lowest], t[lowest]))
print("largest contact force: %.3g N/m (weight %.3g N/m)" % (max(F), m * g))
if lift is None:
    print("lift-off: NO")
    sys.exit(0)
print("lift-off (contact force back to zero) at t = %.3g s" % t[lift])
apex = max(range(lowest, n), key=lambda i: y[i])
print("rebound apex %.3g m at t = %.3g s" % (y[apex], t[apex]))


def velocity(i):
    return (y[i + 1] - y[i - 1]) / (t[i + 1] - t[i - 1])


v_before, v_after = velocity(first - 1), velocity(lift)
v_up = max(velocity(i) for i in range(first, lift + 1))
print("centroid velocity before contact %.3g m/s, largest upward during "
      "contact %.3g m/s: %s" % (v_before, v_up,
                                "rebounds" if v_before < 0 < v_up else "NO rebound"))
impulse = sum(F[i] * (t[i] - t[i - 1]) for i in range(first, lift + 1))
momentum_change = m * (v_after - v_before) + m * g * (t[lift] - t[first - 1])
error = abs(impulse - momentum_change) / abs(momentum_change)
print("impulse of the floor %.3g N s/m, m dv + m g dt %.3g N s/m: within 10%%: %s"
      % (impulse, momentum_change, "yes" if error < 0.1 else "NO (%.2g)" % error))
print("max |volume change| below 1e-6: %s"
      % ("yes" if max(abs(v) for v in s["volume_change"]) < 1e-6 else "NO"))
energy = [k + p + e for k, p, e in zip(s["kinetic_energy"], s["potential_energy"], s["elastic_energy"])]
print("energy after lift-off / initial energy: %.2g" % (energy[lift] / energy[0]))
