"""Compare a run with 'Material/Stress model = dumbbells' with the same
scene run with the macroscopic stress: the columns probe_u_x,
kinetic_energy, elastic_energy, max_velocity, max_velocity_gradient and
min_conformation_eigenvalue, each within TOLERANCE of the column's largest
magnitude over both runs. With alpha = 0 the dumbbells' fields are material
line elements and their ensemble stress is the macroscopic update's up to
round-off (doc/dumbbells.md); the statistics hold 10 significant digits,
so TOLERANCE = 1e-8 leaves room for round-off growth over the run only.
Usage: dumbbells_compare.py DUMBBELLS_DIR MACROSCOPIC_DIR"""
import sys

from vefs_tools import statistics

TOLERANCE = 1e-8
COLUMNS = ["probe_u_x", "kinetic_energy", "elastic_energy", "max_velocity",
           "max_velocity_gradient", "min_conformation_eigenvalue"]


def main(a, b):
    x, y = statistics.read_statistics(a), statistics.read_statistics(b)
    print("rows: %d and %d" % (len(x["step"]), len(y["step"])))
    for name in COLUMNS:
        scale = max(abs(v) for v in x[name] + y[name])
        diff = max(abs(u - v) for u, v in zip(x[name], y[name]))
        if diff <= TOLERANCE * scale:
            print("%s: same to %g" % (name, TOLERANCE))
        else:
            print("%s: DIFFERS, largest difference %.3g (largest value %.3g)"
                  % (name, diff, scale))


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
