#!/usr/bin/env python3
"""Checker of the waters_king_2d test: start-up of planar Poiseuille flow
of an Oldroyd-B fluid against the exact series of Waters & King (1970)
(data/waters_king_1970.md, scripts/waters_king.py).

Usage: waters_king_2d.py OUTPUT_DIR [--bound 0.05]

Scene: 2D channel, no-slip walls y- and y+ at y = y_centre -+ h (h: half
the y extent of the cavity), x periodic, filled with liquid at rest at
t = 0, body force rho g_x (g = (g_x, 0)), i.e. K = -dp/dx = rho g_x; the
probe point (Postprocess/Probe point) on the centreline. With
E = lambda eta0 / (rho h^2), beta = eta_s / eta0, U_inf = K h^2 / (3 eta0)
and T = t / lambda, probe_u_x / U_inf is compared with the series at every
statistics row with 0 < T <= 10. Printed (2-3 significant digits): E, beta,
the largest |U_sim - U_exact| / 1.5 (1.5 = steady centreline velocity),
the simulated and exact first overshoot (value and T), U_sim and U_exact
at T = 1, 2, 5, 10 (U_sim interpolated linearly), and
"max error below <bound>: yes/NO".

The bound (default 0.05, i.e. 5% of the steady centreline velocity) is a
sanity bound for the coarse test run (it catches a wrong sign, a missing
polymer stress or a wrong time scale, all errors of order 1); the accuracy
of the method is measured on finer runs by
benchmarks/viscoelastic_convergence.py. The exit status is non-zero only
if the output cannot be read (missing file, column or parameter); a
failed check shows as NO, which makes numdiff fail.
"""
import sys

from vefs_tools.waters_king import main

if __name__ == "__main__":
    if len(sys.argv) < 2:
        print("usage: waters_king_2d.py OUTPUT_DIR [--bound 0.05]",
              file=sys.stderr)
        sys.exit(1)
    sys.exit(main(sys.argv[1:], prog="waters_king_2d.py"))
