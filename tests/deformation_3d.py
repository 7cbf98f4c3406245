"""LeVeque's 3D deformation of a sphere, period 3, at CFL 5 with finest
cells 1/32. Exact final shape: the initial sphere. At this resolution the
stretched sheet is thinner than a cell and part of it is lost (the volume
correction puts the volume back on the rest of the surface), so the bound
on the relative L1 error is loose: 1.0; thickness bound 2 finest cells.
Measured: 0.852 with the linear interpolation at the feet, 0.498 with the
gradient-augmented level set of issue 11, 0.366 with its four-stage trace,
0.207 with remap distance 10 and 0.141 with 14 (automatic)."""
import sys

from transport_check import check

check(sys.argv[1], 1.0, 2.0)
