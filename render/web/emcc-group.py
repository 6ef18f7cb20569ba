#!/usr/bin/env python3
"""Compile a group of sources with one emcc process (render/web/meson.build).

    emcc-group.py DEPFILE EMCC [FLAG...] --in SOURCE... --out OBJECT...

emcc's start-up (its Python, its configuration checks) is paid once a
process: the module's ~190 files took 139 s of CPU one process each, 64 s
in groups of 12.  Given several sources, one emcc compiles them all, each
by its own clang as before, with the same flags.  The objects
are written in a scratch directory beside the first OBJECT and moved to
their names; the header dependencies of all of them go to DEPFILE as
the dependencies of the first OBJECT (ninja keeps them per rule)."""

import os
import shutil
import subprocess
import sys


def main(argv):
    depfile = argv[0]
    i, o = argv.index("--in"), argv.index("--out")
    cmd, sources, objects = argv[1:i], argv[i + 1:o], argv[o + 1:]
    if len(sources) != len(objects) or not sources:
        sys.exit("emcc-group: %d sources for %d objects"
                 % (len(sources), len(objects)))
    stems = [os.path.splitext(os.path.basename(s))[0] for s in sources]
    if len(set(stems)) != len(stems):
        sys.exit("emcc-group: two sources of one group share a name")
    scratch = objects[0] + ".dir"
    shutil.rmtree(scratch, ignore_errors=True)
    os.makedirs(scratch)
    # emcc writes NAME.o and, with -MD, NAME.d for every input NAME.c in
    # its working directory
    srcs = [os.path.abspath(s) for s in sources]
    r = subprocess.run(cmd + ["-MD", "-c"] + srcs, cwd=scratch)
    if r.returncode != 0:
        sys.exit(r.returncode)
    deps = []
    for stem, obj in zip(stems, objects):
        os.replace(os.path.join(scratch, stem + ".o"), obj)
        # "NAME.o: dependencies", as clang escapes them
        with open(os.path.join(scratch, stem + ".d")) as f:
            deps.append(f.read().split(": ", 1)[1].rstrip())
    shutil.rmtree(scratch)
    with open(depfile + ".tmp", "w") as f:
        f.write(objects[0] + ": " + " \\\n  ".join(deps) + "\n")
    os.replace(depfile + ".tmp", depfile)


if __name__ == "__main__":
    main(sys.argv[1:])
