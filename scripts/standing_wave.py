#!/usr/bin/env python3
"""Standing gravity wave against linear theory: the command line of
vefs_tools.standing_wave (usage and output there)."""
from vefs_tools.standing_wave import main

if __name__ == "__main__":
    main()
