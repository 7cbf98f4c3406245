#!/usr/bin/env python3
"""Checker of the conformation_not_positive test (see its .cmd): whether the
smallest eigenvalue of the conformation tensor (statistics column
min_conformation_eigenvalue) stays positive in every step of a run.

Usage: conformation_not_positive.py OUTPUT_DIR (named after the update)
"""
import sys

from vefs_tools.statistics import read_statistics


def main(output_dir):
    smallest = min(read_statistics(output_dir)["min_conformation_eigenvalue"])
    print("%s update: smallest eigenvalue of c positive in every step: %s"
          % (output_dir, "yes" if smallest > 0 else "no"))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
