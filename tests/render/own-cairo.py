#!/usr/bin/env python3
"""pango calls the cairo of the `curvefig` that carries cairo in itself.

    own-cairo.py CURVEFIG

A `curvefig` linked with cairo's archive (render/tool/meson.build) opens
pango for the first run of a label that the native fonts hand to it
(render/backends/font-native.c: here a Hebrew word, right to left); the
program names itself libcairo.so.2
(its soname), so that libpangocairo's need of libcairo.so.2 is met by it
and the library is not loaded, and each cairo function pango's libraries
call must be the program's own (one cairo: the context pango draws on is
the program's).  The figure of a
label is rendered with the loader resolving every symbol at once
(LD_BIND_NOW) and reporting its bindings (LD_DEBUG=bindings): no object
other than libcairo.so.2 itself may be bound to a function of
libcairo.so.2, and pango's libraries must be bound to cairo functions of
the program.  Skipped (77) when the program loads libcairo.so.2 itself.
"""
import os
import re
import subprocess
import sys
import tempfile

SCRIPT = r"""local f = figure{ name = "one-label", width = "3cm", height = "2cm" }
f:polyline({ {0, 0}, {1, 1}, {2, 0} })
f:label({1, 1}, "$x^2$ and text", { anchor = "n" })
f:label({1, 0}, "\u{5e9}\u{5dc}\u{5d5}\u{5dd}", { anchor = "s" })
"""

BINDING = re.compile(r"binding file (\S+) \[\d+\] to (\S+) \[\d+\]: "
                     r"normal symbol `([^']+)'")


def main(argv):
    tool = os.path.abspath(argv[1])
    dynamic = subprocess.run(["readelf", "-d", tool], capture_output=True,
                             text=True, check=True).stdout
    if any("(NEEDED)" in line and "libcairo.so" in line
           for line in dynamic.splitlines()):
        print("%s loads libcairo.so itself: nothing to check" % tool)
        return 77
    with tempfile.TemporaryDirectory() as tmp:
        script = os.path.join(tmp, "one-label.lua")
        with open(script, "w") as f:
            f.write(SCRIPT)
        env = dict(os.environ, LD_DEBUG="bindings", LD_BIND_NOW="1")
        run = subprocess.run([tool, "render", script, "-o", tmp, "-f", "pdf"],
                             env=env, capture_output=True, text=True)
        if run.returncode != 0:
            sys.stderr.write(run.stderr[-2000:])
            print("FAIL: the render failed (status %d)" % run.returncode)
            return 1
    stands_for_cairo = any("(SONAME)" in line and "[libcairo.so.2]" in line
                           for line in dynamic.splitlines())
    wrong, own, loaded = [], 0, False
    for m in BINDING.finditer(run.stderr):
        src, dst, name = m.groups()
        loaded = loaded or "libcairo.so" in src or "libcairo.so" in dst
        if "libcairo.so" in dst and "libcairo.so" not in src:
            wrong.append("%s -> %s: %s" % (src, dst, name))
        if dst == tool and name.startswith("cairo_") and "pango" in src:
            own += 1
    for w in wrong[:20]:
        print("FAIL: bound to the shared cairo:", w)
    if own == 0:
        print("FAIL: pango's libraries were bound to no cairo function of "
              "the program (was pango opened?)")
    if stands_for_cairo and loaded:
        print("FAIL: libcairo.so.2 was loaded, though the program is named "
              "so (its soname)")
    if wrong or own == 0 or (stands_for_cairo and loaded):
        return 1
    print("ok: pango's libraries bound to %d cairo functions of the program, "
          "none to libcairo.so.2%s" % (own, " (not loaded)"
                                        if stands_for_cairo else ""))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
