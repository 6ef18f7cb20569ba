#!/usr/bin/env python3
"""Every x86-64 level of the core's hot loops draws the same bytes.

    levels-same.py CURVEFIG FIGURE.lua...

The core keeps its hottest loops (the bicubic patch's evaluation of the
hidden lines, the curves' evaluators) in one copy per x86-64 level
(CF__CLONED, src/core-private.h), chosen at the first call from the
features glibc found; the copies must compute the same doubles (the same
operations, wider vectors, no fused multiply-add).  Each figure is drawn
as SVG and PDF by the copies for this processor and again with glibc's
AVX-512, then AVX2, features masked (GLIBC_TUNABLES), and the files are
compared byte for byte.  Skipped (77) off x86-64.
"""
import os
import platform
import subprocess
import sys
import tempfile

MASKS = ("-AVX512F", "-AVX2")


def render(tool, script, out, mask):
    env = dict(os.environ)
    if mask:
        env["GLIBC_TUNABLES"] = "glibc.cpu.hwcaps=" + mask
    subprocess.run([tool, "render", script, "-o", out, "-f", "svg,pdf"],
                   env=env, check=True, capture_output=True,
                   cwd=os.path.dirname(script))
    return {f: open(os.path.join(out, f), "rb").read()
            for f in sorted(os.listdir(out))}


def main(argv):
    if platform.machine() != "x86_64":
        print("not x86-64: one copy of each loop, skipped")
        return 77
    tool = os.path.abspath(argv[1])
    bad = 0
    for script in argv[2:]:
        with tempfile.TemporaryDirectory() as tmp:
            ref = render(tool, script, os.path.join(tmp, "native"), None)
            for mask in MASKS:
                got = render(tool, script, os.path.join(tmp, mask), mask)
                for name, data in ref.items():
                    if got.get(name) != data:
                        print("FAIL: %s: %s differs with %s masked"
                              % (os.path.basename(script), name, mask))
                        bad += 1
            print("%s: %d files the same at 3 levels"
                  % (os.path.basename(script), len(ref)))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
