#!/usr/bin/env python3
"""Where the 2D stiff ball's contact loss comes from: the ball of
prm/bouncing_ball_2d_stiff.prm vibrating without gravity, free, as a half
ball on a slip wall, and cut by a slip wall, at three resolutions.

Usage (from anywhere):
  /usr/bin/python3 benchmarks/ball_on_wall_vibration.py [--vefs build/vefs]
      [--levels 4 5 6] [--cuts 5]
      [--results-dir benchmarks/results/ball_on_wall]
      [--output benchmarks/results/ball_on_wall_vibration.md] [--no-run]
      [--set 'Solver/Ghost penalty=0.02' ...]

The material, scheme and numerics are the scene's (G = 2000 Pa; the
velocity at the feet by cubic interpolation, PSPG 0.01 and the extended
velocity at the outside vertices of cut cells on walls, as 'automatic'
gives them under gravity; --set 'Solver/Pressure stabilization=0.05'
--set 'Flow/Outside velocity of cut cells=extension' gives the former ones);
gravity is off and the floor is a slip wall.
At t = 0 the velocity is u = (x, -y) 1/s, divergence free and tangent to
the floor y = 0, and the body vibrates freely (about 3 periods in 0.6 s).
The material keeps its energy, so every loss is the scheme's:

- free: the whole ball centred at the origin, away from every wall;
- half ball: the same ball with the floor through its centre. The slip wall
  is the free ball's plane of symmetry: the half ball must lose what the
  free one does;
- cut d mm (--cuts, 5 by default): the ball centred 100 - d mm above the
  floor, which cuts a cap of d mm off: liquid and floor meet at acos(1 -
  d / 100) (18 degrees for 5 mm), with a thin wedge of air beside the
  contact line, as when the falling ball meets the floor.

Each run is one rank, Maximum level = L (finest cells 0.1 m / 2^L),
Bulk level = L - 1, to t = 0.6 s, without visualization output, in
<results-dir>/<shape>_L<L>/.
"""
import argparse
import math
import os

from vefs_tools import REPO_ROOT as ROOT
from vefs_tools.prm import apply_settings, set_entry
from vefs_tools.run import (add_study_arguments, run_serial_scene,
                            write_report)
from vefs_tools.statistics import read_statistics



def shapes(cuts):
    """Name, cavity (lower, upper corner, coarse cells of 0.1 m) and ball
    centre of each run: the free ball, the half ball, and the ball cut by
    the floor by each depth in `cuts` (mm)."""
    return [("free", "-0.2, -0.2", "0.2, 0.2", "4, 4", "0, 0"),
            ("half ball", "-0.2, 0", "0.2, 0.2", "4, 2", "0, 0")] + [
        ("cut %g mm (%.0f degrees)" % (cut, math.degrees(
            math.acos(1 - cut / 100))), "-0.2, 0", "0.2, 0.3", "4, 3",
         "0, %g" % (0.1 - cut / 1000)) for cut in cuts]


def make_prm(text, shape, level, output_dir, settings):
    _, lower, upper, cells, centre = shape
    for path, name, value in [
            ([], "Gravity", "0, 0"),
            (["Cavity"], "Lower corner", lower),
            (["Cavity"], "Upper corner", upper),
            (["Cavity"], "Coarse subdivisions", cells),
            (["Walls"], "y-", "slip"),
            (["Initial liquid"], "Ball center", centre),
            (["Initial liquid"], "Velocity", "x; -y"),
            (["Transport"], "Velocity interpolation", "cubic"),
            (["Solver"], "Pressure stabilization", "0.01"),
            (["Flow"], "Outside velocity of cut cells", "extension at walls"),
            (["Mesh refinement"], "Maximum level", str(level)),
            (["Mesh refinement"], "Bulk level", str(level - 1)),
            (["Time"], "End time", "0.6"),
            (["Output"], "Interval", "0"),
            ([], "Output directory", output_dir)]:
        text = set_entry(text, path, name, value)
    return apply_settings(text, settings)


def energy_lost(statistics):
    """1 - E(end) / E(0), E the kinetic and elastic energy."""
    energy = [k + e for k, e in zip(statistics["kinetic_energy"],
                                    statistics["elastic_energy"])]
    return 1 - energy[-1] / energy[0]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--levels", type=int, nargs="+", default=[4, 5, 6])
    parser.add_argument("--cuts", type=float, nargs="+", default=[5],
                        help="depths (mm) of the caps the floor cuts off")
    add_study_arguments(parser, "ball_on_wall",
                        "ball_on_wall_vibration.md")
    args = parser.parse_args()

    os.makedirs(args.results_dir, exist_ok=True)
    with open(os.path.join(ROOT, "prm", "bouncing_ball_2d_stiff.prm")) as f:
        base = f.read()
    lost = {}
    runs = shapes(args.cuts)
    for shape in runs:
        for level in args.levels:
            name = "%s_L%d" % (shape[0].split(" (")[0].replace(" ", "_"),
                               level)
            out = os.path.join(args.results_dir, name)
            if not args.no_run:
                text = make_prm(base, shape, level, out, args.set)
                if not run_serial_scene(os.path.abspath(args.vefs),
                                        args.results_dir, name, text):
                    continue
            if os.path.exists(os.path.join(out, "statistics")):
                lost[shape[0], level] = energy_lost(read_statistics(out))

    lines = [
        "# The stiff ball vibrating on a slip wall",
        "",
        "`benchmarks/ball_on_wall_vibration.py`: energy lost by t = 0.6 s "
        "(about 3 periods), 1 - E(0.6 s) / E(0), E kinetic + elastic; h the "
        "finest cells." + ("" if not args.set else " Changed entries: %s." %
                            ", ".join("`%s`" % x for x in args.set)),
        "",
        "| shape | " + " | ".join("h = %.2f mm" % (100 / 2 ** level)
                                  for level in args.levels) + " |",
        "|---|" + "---|" * len(args.levels),
    ]
    for shape in runs:
        lines.append("| %s | " % shape[0] + " | ".join(
            "%.1f %%" % (100 * lost[shape[0], level])
            if (shape[0], level) in lost else "-"
            for level in args.levels) + " |")
    lines.append("")
    write_report(args.output, lines)


if __name__ == "__main__":
    main()
