"""Helpers shared by the scripts, benchmarks and test checkers of vefs.

The package lives in scripts/, so a script there imports it as it is (its
own directory is on sys.path); benchmarks/vefs_tools and tests/vefs_tools
are links to it for the same reason. The modules that the test checkers
import (statistics, prm, martin_moyce, waters_king, shear_wave,
standing_wave, bounce) use the standard library only; vtu needs numpy.
"""

import os

#: the repository's root directory
REPO_ROOT = os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__))))
#: published reference data (data/README.md)
DATA_DIR = os.path.join(REPO_ROOT, "data")
