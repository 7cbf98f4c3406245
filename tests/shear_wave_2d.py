#!/usr/bin/env python3
"""Checker of the shear_wave_2d test: standing shear wave of an
incompressible neo-Hookean solid (elastic limit, Material/Alpha = 0,
sigma = G (B - I), G = eta_p / lambda) against the exact solution
u = A sin(k (y - y0)) cos(w t) e_x, w = k sqrt(G/rho), k = 2 pi / L_y
(scripts/shear_wave.py).

Usage: shear_wave_2d.py OUTPUT_DIR [--bound 0.02]

Scene: cavity [x0,x1] x [y0,y1] periodic in x and y, filled with the
solid, u(0) = A sin(k (y - y0)) e_x, sigma(0) = 0, probe point where
sin(k (y - y0)) = 1. The solution is exact at any amplitude: in simple
shear with displacement s(y,t) in x, sigma_xy = G s_y, sigma_xx = G s_y^2,
sigma_yy = 0, nothing depends on x and (u.grad) u = 0, so
rho s_tt = G s_yy, the linear wave equation.

A = probe_u_x(0) / sin(k (y_probe - y0)). Printed: the shear strain
amplitude gamma = A / sqrt(G/rho) (2 significant digits), the number of
periods simulated, the relative frequency error (w_sim - w) / w from the
zero crossings of probe_u_x (3 significant digits), the amplitude loss per
period from the extrema of the full half periods (2 significant digits),
the ratio of the kinetic + elastic energy at the end to that at t = 0
(2 significant digits), and "frequency error below <bound>: yes/NO".

The bound (default 0.02) is a sanity bound for the coarse test run (a
wrong shear modulus, a missing factor of the stress or a solid that does
not oscillate gives errors far beyond it); the accuracy of the method is
measured on finer runs by benchmarks/viscoelastic_convergence.py. The
amplitude loss and the energy ratio (numerical dissipation) are printed
for numdiff, without a verdict. The exit status is non-zero only if the
output cannot be read; a failed check shows as NO, which makes numdiff
fail.
"""
import sys

from vefs_tools.shear_wave import main

if __name__ == "__main__":
    sys.exit(main(sys.argv[1:], prog="shear_wave_2d.py"))
