#!/usr/bin/env python3
"""Plots of a bouncing scene (prm/bouncing_ball_2d_stiff.prm): centroid
height, contact force and contact length, and the kinetic, potential and
elastic energies with their sum, against time; with 'Postprocess/Energy
budget' a fourth panel: what each stage of the steps added to the sum, summed
from the start (the potential change moved from the transport to the
momentum step, whose contact reactions are drawn apart). 2D or 3D: the height is
centroid_z and the contact area replaces the length when the statistics
have those columns (a 3D run).

Usage: /usr/bin/python3 scripts/plot_bounce.py OUTPUT_DIR PNG
"""
import sys

import matplotlib

from vefs_tools.energy_budget import step_shares
from vefs_tools.statistics import height_and_depth_unit, read_statistics

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main(output_dir, png):
    s = read_statistics(output_dir)
    t = s["time"]
    height, per = height_and_depth_unit(s)
    three_d = height == "centroid_z"
    contact = ("contact area (m^2)" if three_d else "contact length (m)")
    budget = "energy_change_transport" in s
    fig, axes = plt.subplots(1, 4 if budget else 3,
                             figsize=(17 if budget else 13, 3.8))
    axes[0].plot(t, s[height])
    axes[0].set_ylabel("centroid height (m)")
    axes[1].plot(t, s["contact_force"])
    ax = axes[1].twinx()
    ax.plot(t, s["contact_area" if three_d else "contact_length"], "C1")
    axes[1].set_ylabel("contact force (N%s)" % per)
    ax.set_ylabel(contact, color="C1")
    potential = [p - s["potential_energy"][-1] for p in s["potential_energy"]]
    total = [k + p + e for k, p, e in zip(s["kinetic_energy"], potential,
                                          s["elastic_energy"])]
    axes[2].plot(t, s["kinetic_energy"], label="kinetic")
    axes[2].plot(t, potential, label="potential (from the last value)")
    axes[2].plot(t, s["elastic_energy"], label="elastic")
    axes[2].plot(t, total, "k", label="sum")
    axes[2].set_ylabel("energy (J%s)" % per)
    axes[2].legend(fontsize=7)
    if budget:
        # Each stage's own share; the contact reactions are a part of the
        # momentum step's, drawn apart.
        labels = {
            "transport": "transport (less the potential change)",
            "momentum": "momentum step (with gravity's work)",
            "extension": "extension",
            "stress_update": "stress update",
            "contact": "of the momentum step: contact reactions",
        }
        scheme = [0.0] * len(t)
        for name, changes in step_shares(s).items():
            if changes is None:
                continue
            added, running = [], 0.0
            for change in changes:
                running += change
                added.append(running)
            if name != "contact":
                scheme = [a + b for a, b in zip(scheme, added)]
            axes[3].plot(t, added, "C1--" if name == "contact" else "-",
                         label=labels[name])
        axes[3].plot(t, scheme, "k", label="all stages: the scheme's")
        axes[3].set_ylabel("energy added since t = 0 (J%s)" % per)
        axes[3].legend(fontsize=7)
    for a in axes:
        a.set_xlabel("t (s)")
        a.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    print("wrote %s" % png)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
