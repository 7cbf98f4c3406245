"""Checker of bouncing_ball_2d_predicted: the stiff 2D ball falls (no
contact yet) with the band refined ahead of the surface.

Before each advection the mesh is refined around the present and the
predicted surface (statistics column advected_cells: the cells of the
mesh the advection ran on). The surface moves less than one finest cell
a step here (largest CFL printed), so the band around the predicted
surface overlaps the present band but for a layer of at most one cell:
the mesh the advection ran on may exceed the mesh of the step before by
a few percent, bound 1.25. A prediction that puts the liquid's inside
at the surface refines the whole liquid (1.56 on average when psi was
lifted to 0 inside the liquid). Also printed: the volume change (bound
1e-6)."""
import sys

from vefs_tools.statistics import read_statistics

s = read_statistics(sys.argv[1])
cells, advected = s["cells"], s["advected_cells"]
ratio = max(advected[i] / cells[i - 1] for i in range(1, len(cells)))
print("largest CFL: %.2g" % max(s["cfl"]))
print("largest advected cells / cells of the step before: %.3g" % ratio)
print("refined ahead around the surface only (ratio <= 1.25): %s"
      % ("yes" if ratio <= 1.25 else "NO"))
volume = max(abs(v) for v in s["volume_change"])
print("largest |volume change| below 1e-6: %s" % ("yes" if volume < 1e-6 else "NO"))
