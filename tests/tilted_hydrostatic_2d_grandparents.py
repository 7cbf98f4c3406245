"""Checker: scripts/tilted_hydrostatic.py (tilted hydrostatic rest, u = 0;
bounds there)."""
import os
import runpy

runpy.run_path(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..",
                            "scripts", "tilted_hydrostatic.py"),
               run_name="__main__")
