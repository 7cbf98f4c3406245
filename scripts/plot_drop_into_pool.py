#!/usr/bin/env python3
"""Volume and energy of the tutorial's drop falling into a pool
(prm/drop_into_pool_2d.prm, doc/tutorial.md) against time, from the
statistics: the relative volume change and the initial volume against the
exact area (optionally a run without volume correction); the kinetic and
potential energy above the state of rest (all the liquid a flat layer on
the floor) and their sum; with 'Postprocess/Energy budget', what the
transport and the flow steps added to the sum since t = 0.

Usage: /usr/bin/python3 scripts/plot_drop_into_pool.py OUTPUT_DIR PNG
           [--exact-area A] [--uncorrected DIR]
"""
import argparse

import matplotlib

from vefs_tools.statistics import read_statistics
from vefs_tools.prm import read_parameters, parameter_float, parameter_floats

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def rest_potential(prm, volume):
    """Potential energy (J/m) of the liquid as a flat layer on the floor of
    the cavity, the lowest state: rho g W H^2 / 2 above y = lower corner,
    H = volume / W."""
    rho = parameter_float(prm, "Material/Density")
    g = -parameter_floats(prm, "Gravity")[1]
    lower = parameter_floats(prm, "Cavity/Lower corner")
    upper = parameter_floats(prm, "Cavity/Upper corner")
    width = upper[0] - lower[0]
    height = volume / width
    return rho * g * width * height * height / 2 + rho * g * volume * lower[1]


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("output_dir")
    p.add_argument("png")
    p.add_argument("--exact-area", type=float, default=0.2 * 0.05
                   + 3.141592653589793 * 0.02 ** 2,
                   help="exact liquid area (m^2); default: the tutorial's")
    p.add_argument("--uncorrected", help="output directory of the same "
                   "scene with 'Transport/Volume correction = false'")
    a = p.parse_args(argv)
    s = read_statistics(a.output_dir)
    prm = read_parameters(a.output_dir)
    t = s["time"]
    budget = "energy_change_transport" in s
    fig, axes = plt.subplots(1, 3 if budget else 2,
                             figsize=(15 if budget else 10, 3.8))

    ax = axes[0]
    ax.semilogy(t, [abs(v) for v in s["volume_change"]],
                label="|volume_change|")
    ax.semilogy(t, [abs(v / a.exact_area - 1) for v in s["volume"]],
                label="|volume / exact area - 1|")
    if a.uncorrected:
        u = read_statistics(a.uncorrected)
        ax.semilogy(u["time"][1:], [abs(v) for v in u["volume_change"][1:]],
                    "--", label="|volume_change|, no volume correction")
    ax.set_ylabel("relative volume error")
    ax.legend(fontsize=7)

    rest = rest_potential(prm, s["volume"][0])
    potential = [x - rest for x in s["potential_energy"]]
    total = [k + x for k, x in zip(s["kinetic_energy"], potential)]
    ax = axes[1]
    ax.plot(t, s["kinetic_energy"], label="kinetic")
    ax.plot(t, potential, label="potential above rest")
    ax.plot(t, total, "k", label="sum")
    ax.set_ylabel("energy (J/m)")
    ax.legend(fontsize=7)

    if budget:
        ax = axes[2]
        scheme = [0.0] * len(t)
        for stage in ["transport", "flow"]:
            running, added = 0.0, []
            for i, change in enumerate(s["energy_change_" + stage]):
                running += change if i > 0 else 0.0
                added.append(running)
                scheme[i] += running
            ax.plot(t, added, label=stage)
        ax.plot(t, scheme, "k", label="both: the sum's change")
        ax.set_ylabel("energy added since t = 0 (J/m)")
        ax.legend(fontsize=7)
    for ax in axes:
        ax.set_xlabel("t (s)")
        ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(a.png, dpi=100)
    print("wrote %s" % a.png)


if __name__ == "__main__":
    main()
