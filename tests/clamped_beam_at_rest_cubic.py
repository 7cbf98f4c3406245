"""Checker of clamped_beam_at_rest_cubic: the stiff beam at rest of
clamped_beam_at_rest with the limited cubic velocity (and so stress)
interpolation. The same checks against the same references (the sum of
the energies within 1 % of its start, the mean sag within 10 % of the
Timoshenko cantilever's): see clamped_beam_at_rest.py, which this runs."""
import os
import runpy

runpy.run_path(os.path.join(os.path.dirname(os.path.abspath(__file__)),
                            "clamped_beam_at_rest.py"),
               run_name="__main__")
