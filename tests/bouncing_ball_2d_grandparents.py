"""Checker of bouncing_ball_2d_grandparents: the stiff ball of
bouncing_ball_2d_stiff with 'Flow/Flow cells = grandparents'. The same
checks against the same references (Newton's second law for the centroid
over the contact within 1 % and in each step within 3 % of the largest
step impulse, volume change below 1e-6, a rebound and a
lift-off, at least 0.8 of the energy left after the bounce, the energy
budget closing every step): see
bouncing_ball_2d_stiff.py, which this runs."""
import os
import runpy

runpy.run_path(os.path.join(os.path.dirname(os.path.abspath(__file__)),
                            "bouncing_ball_2d_stiff.py"),
               run_name="__main__")
