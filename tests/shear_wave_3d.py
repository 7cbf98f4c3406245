#!/usr/bin/env python3
"""Checker of the shear_wave_3d test: the standing shear wave of the
neo-Hookean solid of shear_wave_2d (see scripts/shear_wave.py for the exact
solution and the analysis), in 3D between slip walls z- and z+: the exact
solution does not depend on z, so the 3D code (stress components in 3D,
3D eigenvalues of B) must give the 2D numbers. Bound on the frequency
error: 2% (h = 1/16, tau = T/100; the 2D test gives -1.42%)."""
import sys

from vefs_tools.shear_wave import main

if __name__ == "__main__":
    sys.exit(main(sys.argv[1:], prog="shear_wave_3d.py"))
