#!/usr/bin/env python3
"""Rewrite .prm files for the subsections of this version (doc/parameters.prm).

Entries that moved from one top-level subsection to another (the list is
vefs' Parameters::moved_entries in source/core/parameters.cc) are taken out
of their old subsection, with their trailing comments, and put into the new
one: at the end of that subsection if the file has it, else in a new block
after the old one. An old subsection left with nothing is removed. vefs
still reads the old places, with a warning; this script silences it.

Usage: migrate_prm.py FILE.prm [FILE.prm ...]   (rewrites in place)
"""
import re
import sys

MOVED = {
    ("Mesh refinement", name): "Transport"
    for name in ["Level set interpolation", "Velocity interpolation",
                 "Stress interpolation", "Remap distance",
                 "Redistancing interval", "Volume correction"]}
MOVED.update({("Mesh refinement", name): "Flow"
              for name in ["Flow cells", "Extension layers",
                           "Outside velocity of cut cells",
                           "Outside stress of cut cells"]})
MOVED.update({("Solver", name): "Stress"
              for name in ["Stress update", "Stress theta"]})

SUBSECTION = re.compile(r"^\s*subsection\s+(.*?)\s*(#.*)?$")
END = re.compile(r"^\s*end\s*(#.*)?$")
SET = re.compile(r"^\s*set\s+(.*?)\s*=")


def normalized(name):
    return " ".join(name.split())


def migrate(lines):
    """The lines with the moved entries in their new subsections."""
    path, kept, moved = [], [], {}
    # Where each top-level block ends in kept (index of its 'end' line).
    block_end = {}
    block_start = {}
    for line in lines:
        match = SUBSECTION.match(line)
        if match:
            path.append(normalized(match.group(1)))
            if len(path) == 1:
                block_start[path[0]] = len(kept)
            kept.append(line)
            continue
        if END.match(line) and path:
            if len(path) == 1:
                block_end[path[0]] = len(kept)
            path.pop()
            kept.append(line)
            continue
        match = SET.match(line)
        if match and len(path) == 1:
            target = MOVED.get((path[0], normalized(match.group(1))))
            if target:
                # The comment lines just above belong to the entry.
                comments = []
                while kept and kept[-1].strip().startswith("#"):
                    comments.insert(0, "  " + kept.pop().strip() + "\n")
                moved.setdefault(target, []).append(
                    (path[0], comments, "  " + line.strip() + "\n"))
                continue
        kept.append(line)
    if not moved:
        return lines
    # Insert into existing blocks from the last one backwards, so that the
    # recorded indices stay valid; new blocks go after their old one.
    insertions = []
    for target, entries in moved.items():
        sets = aligned([text for _, _, text in entries])
        body = [line for (_, comments, _), text in zip(entries, sets)
                for line in comments + [text]]
        if target in block_end:
            insertions.append((block_end[target], body))
        else:
            old = entries[0][0]
            insertions.append((block_end[old] + 1,
                               ["subsection " + target + "\n"] + body +
                               ["end\n"]))
    for index, body in sorted(insertions, key=lambda x: -x[0]):
        kept[index:index] = body
    return drop_empty_blocks(kept)


def aligned(lines):
    """'set NAME = VALUE' lines with their '=' in one column (a comment
    after the value stays with it)."""
    parts = [line.strip()[4:].split("=", 1) for line in lines]
    width = max(len(name.strip()) for name, _ in parts)
    return ["  set " + name.strip().ljust(width) + " = " + value.strip() +
            "\n" for name, value in parts]


def drop_empty_blocks(lines):
    """Remove top-level subsections that hold no 'set' and no subsection."""
    result, block = [], None
    depth = 0
    for line in lines:
        if depth == 0 and SUBSECTION.match(line):
            block = [line]
            depth = 1
            continue
        if block is not None:
            block.append(line)
            if SUBSECTION.match(line):
                depth += 1
            elif END.match(line):
                depth -= 1
                if depth == 0:
                    if any(SET.match(l) for l in block[1:-1]):
                        result.extend(block)
                    block = None
            continue
        result.append(line)
    return result


def main():
    for name in sys.argv[1:]:
        with open(name) as file:
            lines = file.readlines()
        new = migrate(lines)
        if new != lines:
            with open(name, "w") as file:
                file.writelines(new)
            print("migrated", name)


if __name__ == "__main__":
    main()
