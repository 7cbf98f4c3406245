#!/usr/bin/env python3
"""Compare a 2D broken-dam run of vefs with Martin & Moyce (1952), n^2 = 2:
the command line of vefs_tools.martin_moyce (usage and output there;
reference data in data/)."""
import sys

from vefs_tools.martin_moyce import main

if __name__ == "__main__":
    sys.exit(main())
