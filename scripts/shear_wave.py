#!/usr/bin/env python3
"""Standing shear wave of a neo-Hookean solid against its exact solution:
the command line of vefs_tools.shear_wave (usage and output there)."""
import sys

from vefs_tools.shear_wave import main

if __name__ == "__main__":
    sys.exit(main())
