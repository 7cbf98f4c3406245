#!/usr/bin/env python3
"""Checker of the waters_king_2d_dumbbells test: the start-up flow of
waters_king_2d.py with the polymer stress carried by N_f = 100 Hookean
dumbbells (Brownian configuration fields, seed 1; doc/dumbbells.md)
instead of the Oldroyd-B law, against the exact series of Waters & King
(1970). Printed as by waters_king_2d.py.

The bound is statistical: with beta = 1/9 the solvent carries a ninth of
the shear stress, so the dumbbells' noise in the polymer stress shows
nine-fold in the velocity. benchmarks/dumbbells_waters_king.py measured
the largest |U_sim - U_exact| / 1.5 at N_f = 100 as 0.43-0.50 over three
seeds (its RMS falls like N_f^(-1/2) to 1600 fields); the bound 1 catches
what is not noise: without the polymer stress the velocity would rise to
9 times U_inf (error above 5), without the relaxation the elastic
oscillation would not decay.

Usage: waters_king_2d_dumbbells.py OUTPUT_DIR
"""
import sys

from vefs_tools.waters_king import main

if __name__ == "__main__":
    if len(sys.argv) != 2:
        print("usage: waters_king_2d_dumbbells.py OUTPUT_DIR", file=sys.stderr)
        sys.exit(1)
    sys.exit(main([sys.argv[1], "--bound", "1"],
                  prog="waters_king_2d_dumbbells.py"))
