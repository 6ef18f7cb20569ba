#!/usr/bin/env python3
"""The figure scripts that seed the script target's fuzz pass.

Every figure script of figures/ (recursively) is a seed, but those that
draw a surface (f:surface, f:decasteljau_surface, f:triangle_scheme):
in the fuzz build (coverage and comparison tracing in every library,
AddressSanitizer) the hidden lines of a surface figure take 1 to 24 s an
execution, 300 times the 40 ms of the others, so that the ten surface
figures alone took more than the target's whole share of the pass to
run once, and the search never began.  The surface drawing of the
language is seeded by tests/fuzz/corpus/script/surfaces/ (small
patches), the hidden-line core is fuzzed by fuzz_visibility and
fuzz_surfaces, and the replay of the normal test run (no
instrumentation) still runs every figure.

  figure-seeds.py FIGURES_DIR OUT_DIR STAMP
      copy the seeds to OUT_DIR (and remove the others there), touch STAMP
"""
import os
import re
import shutil
import sys

SURFACE = re.compile(r":\s*(surface|decasteljau_surface|triangle_scheme)\s*\(")


def seeds(figures):
    out = {}
    for root, dirs, files in os.walk(figures):
        dirs.sort()
        for name in sorted(files):
            if not name.endswith(".lua"):
                continue
            path = os.path.join(root, name)
            with open(path, encoding="utf-8") as f:
                if SURFACE.search(f.read()):
                    continue
            rel = os.path.relpath(path, figures)
            out[rel.replace(os.sep, "-")] = path
    return out


def main(argv):
    if len(argv) != 4:
        sys.stderr.write(__doc__)
        return 2
    figures, out_dir, stamp = argv[1:]
    want = seeds(figures)
    os.makedirs(out_dir, exist_ok=True)
    for name in os.listdir(out_dir):
        if name not in want:
            os.remove(os.path.join(out_dir, name))
    for name, path in want.items():
        shutil.copyfile(path, os.path.join(out_dir, name))
    with open(stamp, "w") as f:
        f.write("%d figure seeds\n" % len(want))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
