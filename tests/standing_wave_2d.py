"""Standing gravity wave against linear theory (scripts/standing_wave.py:
omega^2 = g k tanh(k d), viscous decay exp(-2 nu k^2 t); Lamb,
Hydrodynamics, sections 227-229 and 348). Printed with 2 significant
digits: the frequency error and the numerical amplitude loss per period,
and whether they are within the bounds of this coarse run (h = L/64,
tau = T/40, 1.5 periods): |frequency error| below 1 % and amplitude loss
below 5 % per period. The finer runs of benchmarks/standing_wave.py
(doc/standing_wave.md) measure the accuracy."""
import sys

from vefs_tools.standing_wave import measure

m = measure(sys.argv[1])
print("exact period: %.4f s" % m["exact_period"])
print("frequency error: %.2g" % m["frequency_error"])
print("numerical amplitude loss per period: %.2g"
      % m["amplitude_loss_per_period"])
print("|frequency error| below 0.01: %s"
      % ("yes" if abs(m["frequency_error"]) < 0.01 else "NO"))
print("amplitude loss below 0.05 per period: %s"
      % ("yes" if m["amplitude_loss_per_period"] < 0.05 else "NO"))
