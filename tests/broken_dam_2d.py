#!/usr/bin/env python3
"""Checker of the broken_dam_2d test: the Martin & Moyce (1952) comparison
(data/martin_moyce_1952_n2_2_*.csv) of the run in sys.argv[1].
The test mesh is one level coarser than prm/broken_dam_2d.prm, so the verdict
thresholds are those measured acceptable at this resolution: residual height
within 5%, front within 8% after a time shift of at most 0.3, volume kept
to 0.5%. The printed errors themselves are compared by numdiff."""
import sys

from vefs_tools.martin_moyce import main

sys.exit(main([sys.argv[1], "--height-threshold", "0.05",
               "--front-threshold", "0.08", "--volume-threshold", "0.005"]))
