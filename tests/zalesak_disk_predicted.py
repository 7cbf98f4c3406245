"""Zalesak's slotted disk after one revolution at CFL 10 with the band
refined ahead of the surface. Exact final shape: the initial disk. Bounds
as in zalesak_disk.py (relative L1 error 0.12, interface thickness 2 finest
cells). The band must have kept up with the surface: after every advection
no cell the surface crosses may be coarser than the finest level (the
statistics column coarse_surface_cells, exact: 0)."""
import sys

from transport_check import check
from vefs_tools.statistics import read_statistics

check(sys.argv[1], 0.12, 2.0)
coarse = read_statistics(sys.argv[1])["coarse_surface_cells"][1:]
print("surface in the finest cells after every advection: %s"
      % ("yes" if max(coarse) == 0 else "NO (%d cells)" % max(coarse)))
