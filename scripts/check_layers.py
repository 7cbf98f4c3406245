#!/usr/bin/env python3
"""Check that vefs' folders form layers (doc/code.md, "Folders and layers").

Each folder of include/vefs/ and source/ may include headers of its own
folder and of the folders below it in LAYERS, never of one above: no arrow
of the include graph runs up. Each source/<folder>/NAME.cc has its header in
include/vefs/<folder>/ (the two trees mirror each other). Prints the arrows
that run up and the sources without a header beside them; exits 1 if there
are any.

Usage: check_layers.py [repository root]
"""
import pathlib
import re
import sys

# Lowest first.
LAYERS = ["base", "compat", "fields", "transport", "stress", "flow", "io",
          "core"]

INCLUDE = re.compile(r'#include <vefs/([a-z_]+)/([a-z_0-9]+)\.h>')


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else
                        pathlib.Path(__file__).resolve().parent.parent)
    problems = []
    files = sorted(list((root / "include" / "vefs").glob("*/*.h")) +
                   list((root / "source").glob("*/*.cc")))
    for path in files:
        folder = path.parent.name
        relative = path.relative_to(root)
        if folder not in LAYERS:
            problems.append(f"{relative}: folder '{folder}' is not a layer")
            continue
        for target, name in INCLUDE.findall(path.read_text()):
            if target not in LAYERS:
                problems.append(f"{relative}: includes vefs/{target}/{name}.h"
                                f" of no layer")
            elif LAYERS.index(target) > LAYERS.index(folder):
                problems.append(f"{relative}: {folder} -> {target} "
                                f"({name}.h) runs up")
        if path.suffix == ".cc" and not (root / "include" / "vefs" / folder /
                                         (path.stem + ".h")).exists():
            problems.append(f"{relative}: no include/vefs/{folder}/"
                            f"{path.stem}.h")
    print("layers, lowest first: " + " ".join(LAYERS))
    print(f"files checked: {'yes' if files else 'none found'}")
    print(f"problems: {len(problems)}")
    for problem in problems:
        print("  " + problem)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
