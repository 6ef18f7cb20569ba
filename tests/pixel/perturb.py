#!/usr/bin/env python3
"""Write a copy of a figure script with one control point moved.

    perturb.py IN OUT OLD NEW

Replaces the text OLD (a point literal such as "{3,3}") by NEW exactly once
in the line that defines the control points (`local P = ...`) and fails if
it is not found exactly once there, so that the perturbation test cannot
silently test nothing when the figure script changes.
"""
import sys


def main():
    src, dst, old, new = sys.argv[1:5]
    with open(src, encoding="utf-8") as f:
        lines = f.readlines()
    hits = [i for i, l in enumerate(lines)
            if l.lstrip().startswith("local P =") and l.count(old) == 1]
    if len(hits) != 1:
        sys.exit("perturb.py: %s: expected one `local P =` line containing "
                 "%s once, found %d" % (src, old, len(hits)))
    lines[hits[0]] = lines[hits[0]].replace(old, new)
    with open(dst, "w", encoding="utf-8") as f:
        f.writelines(lines)


main()
