"""Checker of bouncing_ball_2d_local: bouncing_ball_2d_soft with
'Time/Strain bound = local'. The same exact properties as that test's
checker (B positive definite, volume kept, no energy gained after the first
contact, centroid between the floor and its initial height), printed by it,
and one more that defines the entry: the bound does not shorten the steps,
so every step is 'Time/Time step' (0.025 s) long and 0.4 s takes 16 steps."""
import os
import runpy
import sys

here = os.path.dirname(os.path.abspath(__file__))
runpy.run_path(os.path.join(here, "bouncing_ball_2d_soft.py"), run_name="__main__")

from vefs_tools.statistics import read_statistics

s = read_statistics(sys.argv[1])
steps = s["tau"][1:]
print("steps: %d, all 0.025 s long: %s"
      % (len(steps), "yes" if all(abs(tau - 0.025) < 1e-12 for tau in steps) else "NO"))
