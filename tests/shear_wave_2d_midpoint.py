#!/usr/bin/env python3
"""Checker of the shear_wave_2d_midpoint test: the scene and report of
shear_wave_2d (see tests/shear_wave_2d.py: the standing shear wave of a
neo-Hookean solid against its exact solution, scripts/shear_wave.py), run
with the midpoint rule (Stress/Stress theta = 0.5, exponential update).

Usage: shear_wave_2d_midpoint.py OUTPUT_DIR

Besides the frequency error (sanity bound 0.02), the amplitude loss per
period must stay below 0.01: the exact wave keeps its amplitude, the
midpoint rule keeps the energy of this oscillation (0.0038 per period on
this mesh and step), and the seed's backward Euler loses 0.18 per period,
so the verdict tells the two apart. The exit status is non-zero only if
the output cannot be read; a failed check shows as NO, which makes numdiff
fail.
"""
import sys

from vefs_tools.shear_wave import main

if __name__ == "__main__":
    sys.exit(main(sys.argv[1:] + ["--loss-bound", "0.01"],
                  prog="shear_wave_2d_midpoint.py"))
