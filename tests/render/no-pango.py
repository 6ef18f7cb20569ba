#!/usr/bin/env python3
"""A labelled figure of the course does not load pango.

    no-pango.py CURVEFIG FIGURE.lua...

The native fonts (render/backends/font-native.c) shape the labels of the
course with the renderer's own shaper or HarfBuzz; pango is opened only
for a run they hand to it (right-to-left text, emoji, a character no font
has: own-cairo.py renders one).  Each figure is rendered as PDF, SVG and
PNG with the loader reporting the objects it loads (LD_DEBUG=files):
FreeType (the labels' glyphs, drawn through cairo) must be among them and
libpango must not.  (Whether HarfBuzz is loaded is lazy-harfbuzz.py's
question: these figures' labels are simple and do not load it.)
"""
import os
import re
import subprocess
import sys
import tempfile

LOADED = re.compile(r"file=(\S+)")


def main(argv):
    tool = os.path.abspath(argv[1])
    bad = 0
    for script in argv[2:]:
        with tempfile.TemporaryDirectory() as tmp:
            env = dict(os.environ, LD_DEBUG="files")
            run = subprocess.run([tool, "render", script, "-o", tmp,
                                  "-f", "pdf,svg,png"], env=env,
                                 capture_output=True, text=True,
                                 cwd=os.path.dirname(script))
            if run.returncode != 0:
                sys.stderr.write(run.stderr[-2000:])
                print("FAIL: %s: the render failed (status %d)"
                      % (script, run.returncode))
                bad += 1
                continue
            objects = set(os.path.basename(m.group(1))
                          for m in LOADED.finditer(run.stderr))
            pango = sorted(o for o in objects if o.startswith("libpango"))
            if pango:
                print("FAIL: %s loaded %s" % (script, ", ".join(pango)))
                bad += 1
            elif not any(o.startswith("libfreetype") for o in objects):
                print("FAIL: %s loaded no FreeType: were its labels set?"
                      % script)
                bad += 1
            else:
                print("ok: %s: %d objects, FreeType, no pango"
                      % (os.path.basename(script), len(objects)))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
