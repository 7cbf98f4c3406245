#!/usr/bin/env python3
# Checker of the broken_dam_2d test: prints the Martin & Moyce comparison of the run in sys.argv[1].
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scripts"))
from compare_martin_moyce import main
sys.exit(main(sys.argv[1:]))
