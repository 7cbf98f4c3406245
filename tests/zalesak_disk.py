"""Zalesak's slotted disk after one revolution at CFL 5, finest cells 1/128.
Exact final shape: the initial disk. Bounds: relative L1 error 0.12 (the
slot, 6 cells wide, has its corners rounded; 0.084 measured when the test was
written with the linear interpolation at the feet, 0.045 with the
gradient-augmented level set of issue 11, 0.0032 with its four-stage
trace, 0.0023 with the remap distance 20 and the level set kept within 40
cells at redistancing), interface thickness 2 finest cells (issue 3)."""
import sys

from transport_check import check

check(sys.argv[1], 0.12, 2.0)
