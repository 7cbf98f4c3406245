"""Checker: tests/drop_into_pool_2d.py (exact liquid area at every step,
free fall before the contact; references there)."""
import os
import runpy

runpy.run_path(os.path.join(os.path.dirname(os.path.abspath(__file__)),
                            "drop_into_pool_2d.py"),
               run_name="__main__")
