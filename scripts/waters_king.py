#!/usr/bin/env python3
"""Start-up Poiseuille flow of an Oldroyd-B fluid against Waters & King
(1970): the command line of vefs_tools.waters_king (usage there; without
arguments the self-check of the series)."""
import sys

from vefs_tools.waters_king import main

if __name__ == "__main__":
    sys.exit(main())
