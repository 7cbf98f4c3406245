"""Filling a tank through a 'velocity' wall (tests/filling_2d.prm).

Exact answers:
- With the volume correction the liquid volume is the expected one at every
  step: |volume_change| below 1e-9 (the correction's target is met to
  round-off). The outflow of a step is taken from the expected volume after
  the step's statistics, so the column compares each step with its own
  target (reported the other way round it showed each step's inflow,
  7e-4).
- What the flow lets in over a step n is tau_n u h_n, u = 0.05 m/s the
  imposed velocity and h_n the wet height of the wall ('wall_height', the
  crossing of the Q1 level set on the wall): after N steps
  V_N - V_0 = sum over n = 1 .. N-1 of tau_n u h_n (the inflow measured
  after step n enters the volume of step n + 1). Bound: relative difference
  below 1e-6 (counting the whole faces of cut cells instead of their wet
  parts made it 12 %)."""
import sys

from vefs_tools.statistics import read_statistics

s = read_statistics(sys.argv[1])
n_steps = len(s["step"]) - 1
u = 0.05
let_in = sum(s["tau"][n] * u * s["wall_height"][n] for n in range(1, n_steps))
gained = s["volume"][-1] - s["volume"][0]
print("steps run: %d" % n_steps)
print("max |volume change| below 1e-9: %s"
      % ("yes" if max(abs(v) for v in s["volume_change"]) < 1e-9 else "NO"))
print("volume gained over the initial volume: %.3f" % (gained / s["volume"][0]))
print("volume gained against u times the wall's wet height, relative "
      "difference below 1e-6: %s"
      % ("yes" if abs(gained / let_in - 1) < 1e-6 else "NO"))
