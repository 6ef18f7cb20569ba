#!/usr/bin/env python3
"""`curvefig compare`: its verdicts, exit status and messages.

    test_compare.py TOOL

Renders a small figure of its own (and variants of it) with TOOL into a
temporary directory and compares the files: the same picture (exit 0),
anti-aliasing only (exit 0, and 1 with the allowance off), a moved control
point (exit 1, with a diff image), and the errors (exit 2): a missing file,
a file that is not an image, a truncated PNG, a PDF, sizes that differ,
bad usage, a diff image that cannot be written.
"""
import os
import struct
import subprocess
import sys
import tempfile
import zlib

FIGURE = """
local c = bezier{ {0, 0}, {1, 2}, {%s, 2}, {4, 0} }
local f = figure{ name = "%s", width = "4cm", height = "3cm",
                  window = { -0.5, 4.5, -0.5, 2.5 } }
f:polygon(c)
f:curve(c)
f:points(c)
f:label({1, 2}, "b_1", { place = "n" })
"""

failures = []


def check(what, cond, detail=""):
    if not cond:
        failures.append(what + (": " + detail if detail else ""))
        print("FAIL", what, detail)
    else:
        print("ok  ", what)


def run(tool, *args):
    return subprocess.run([tool] + list(args), capture_output=True,
                          text=True)


def png_size(path):
    with open(path, "rb") as f:
        head = f.read(24)
    return struct.unpack(">II", head[16:24])


def render(tool, tmp, name, x, dpi="144", labels=True):
    script = os.path.join(tmp, name + ".lua")
    with open(script, "w", encoding="utf-8") as f:
        f.write(FIGURE % (x, name))
    out = os.path.join(tmp, "dpi" + dpi + ("" if labels else "-nolabels"))
    args = ["render", script, "-o", out, "-f", "svg,png", "--dpi", dpi]
    if not labels:
        args.append("--no-labels")
    r = run(tool, *args)
    if r.returncode != 0:
        sys.exit("cannot render %s: %s" % (script, r.stderr))
    return os.path.join(out, name)


def main():
    tool = os.path.abspath(sys.argv[1])
    with tempfile.TemporaryDirectory() as tmp:
        base = render(tool, tmp, "base", "3")
        again = render(tool, tmp, "again", "3")
        moved = render(tool, tmp, "moved", "3.1")
        nudged = render(tool, tmp, "nudged", "3.003")
        plain = render(tool, tmp, "base", "3", labels=False)
        big = render(tool, tmp, "base", "3", dpi="150")

        r = run(tool, "compare", base + ".png", again + ".png")
        check("the same figure twice: exit 0", r.returncode == 0, r.stdout)
        check("the same figure twice: identical",
              "same: the" in r.stdout and "pixels are identical" in r.stdout,
              r.stdout)
        w, h = png_size(base + ".png")
        check("the sizes are printed",
              "%dx%d pixels" % (w, h) in r.stdout, r.stdout)

        # the SVG rasterised by librsvg against cairo's PNG: one picture
        r = run(tool, "compare", plain + ".svg", plain + ".png")
        check("SVG against its PNG, no labels: exit 0", r.returncode == 0,
              r.stdout + r.stderr)
        check("the SVG is said to be rasterised at 144 dpi",
              "SVG rasterised at 144 dpi" in r.stdout, r.stdout)

        # the tool's own output at its default resolution (150 dpi, in the
        # PNG's pHYs): the SVG is rasterised at the PNG's resolution
        script = os.path.join(tmp, "base.lua")
        own = os.path.join(tmp, "own")
        r = run(tool, "render", script, "-o", own, "-f", "svg,png")
        for a, b in ((".svg", ".png"), (".png", ".svg")):
            r = run(tool, "compare", os.path.join(own, "base" + a),
                    os.path.join(own, "base" + b))
            check("render -f svg,png, then compare base%s base%s: exit 0"
                  % (a, b), r.returncode == 0, r.stdout + r.stderr)
            check("the SVG at the PNG's 150 dpi",
                  "SVG rasterised at 150 dpi" in r.stdout, r.stdout)
        r = run(tool, "compare", big + ".svg", big + ".png")
        check("--dpi 150 files: exit 0", r.returncode == 0,
              r.stdout + r.stderr)

        # a control point moved by 0.1 unit (about 1.6 pt, 3 pixels)
        diff = os.path.join(tmp, "diff.png")
        r = run(tool, "compare", moved + ".png", base + ".png",
                "--diff", diff)
        check("a moved control point: exit 1", r.returncode == 1,
              r.stdout + r.stderr)
        check("a moved control point: 'different' with the count",
              r.stdout.count("different: ") == 1 and "pixels differ (" in
              r.stdout, r.stdout)
        check("the first differing pixels are listed",
              "first differing pixels" in r.stdout, r.stdout)
        check("the diff image is written",
              os.path.isfile(diff) and png_size(diff) == (w, h))
        check("the diff image is named", "diff: " + diff in r.stdout,
              r.stdout)

        # 0.003 units is 0.1 pixel: anti-aliasing only, unless forbidden
        r = run(tool, "compare", nudged + ".png", base + ".png")
        check("a sub-pixel shift: exit 0", r.returncode == 0,
              r.stdout + r.stderr)
        check("a sub-pixel shift: anti-aliasing only",
              "anti-aliasing only" in r.stdout and "same:" in r.stdout,
              r.stdout)
        r = run(tool, "compare", nudged + ".png", base + ".png",
                "--aa-radius", "0", "--threshold", "0.01")
        check("a sub-pixel shift without the allowance: exit 1",
              r.returncode == 1, r.stdout + r.stderr)
        r = run(tool, "compare", moved + ".png", base + ".png",
                "--max-bad", "100%")
        check("--max-bad 100%: exit 0", r.returncode == 0, r.stdout)
        check("--max-bad 100%: within the allowance",
              "within the" in r.stdout, r.stdout)

        # errors: exit 2 and a message naming the file
        missing = os.path.join(tmp, "missing.png")
        r = run(tool, "compare", missing, base + ".png")
        check("a missing file: exit 2", r.returncode == 2)
        check("a missing file: the message",
              missing + ": cannot read it: No such file or directory"
              in r.stderr, r.stderr)

        text = os.path.join(tmp, "notes.txt")
        with open(text, "w") as f:
            f.write("not a picture\n")
        r = run(tool, "compare", base + ".png", text)
        check("not an image: exit 2", r.returncode == 2)
        check("not an image: the message",
              text + ": not an image curvefig can read (a PNG or an SVG"
              in r.stderr, r.stderr)

        truncated = os.path.join(tmp, "truncated.png")
        with open(base + ".png", "rb") as f:
            data = f.read()
        with open(truncated, "wb") as f:
            f.write(data[:len(data) // 2])
        r = run(tool, "compare", truncated, base + ".png")
        check("a truncated PNG: exit 2", r.returncode == 2)
        check("a truncated PNG: the message",
              truncated + ": not a readable PNG file" in r.stderr, r.stderr)

        # a damaged or outsized header, a bad checksum: what is wrong, not
        # the "out of memory" cairo gives for every PNG libpng refuses
        def png_file(name, width, height, crc=True):
            ihdr = b"IHDR" + struct.pack(">IIBBBBB", width, height, 8, 2, 0,
                                         0, 0)
            crc_v = zlib.crc32(ihdr) if crc else 0
            raw = b"".join(b"\0" + b"\x80" * 3 * width
                           for _ in range(min(height, 4)))
            idat = b"IDAT" + zlib.compress(raw)
            path = os.path.join(tmp, name)
            with open(path, "wb") as f:
                f.write(b"\x89PNG\r\n\x1a\n" + struct.pack(">I", 13) + ihdr
                        + struct.pack(">I", crc_v)
                        + struct.pack(">I", len(idat) - 4) + idat
                        + struct.pack(">I", zlib.crc32(idat))
                        + b"\0\0\0\0IEND\xaeB`\x82")
            return path
        for name, size, crc, want in (
                ("zero.png", (0, 0), True, "its header gives 0 x 0 pixels"),
                ("huge.png", (100000, 100000), True,
                 "100000 x 100000 pixels, more than the 32000 a side"),
                ("badcrc.png", (4, 4), False, "libpng refused it: a bad "
                 "checksum")):
            path = png_file(name, *size, crc=crc)
            r = run(tool, "compare", path, base + ".png")
            check("%s: exit 2" % name, r.returncode == 2, r.stderr)
            check("%s: the message says what is wrong" % name,
                  path + ": not a readable PNG file (" + want in r.stderr,
                  r.stderr)
            check("%s: not 'out of memory'" % name,
                  "(out of memory)" not in r.stderr, r.stderr)

        pdf = os.path.join(tmp, "base.pdf")
        r = run(tool, "render", os.path.join(tmp, "base.lua"), "-o", tmp,
                "-f", "pdf")
        r = run(tool, "compare", pdf, base + ".png")
        check("a PDF: exit 2", r.returncode == 2)
        check("a PDF: the message says PDF is not supported",
              pdf + ": a PDF; curvefig compares PNG and SVG files only"
              in r.stderr, r.stderr)

        bw, bh = png_size(big + ".png")
        r = run(tool, "compare", base + ".png", big + ".png")
        check("sizes that differ: exit 2", r.returncode == 2)
        check("sizes that differ: both sizes in the message",
              "the sizes differ: %s.png is %dx%d pixels, %s.png is %dx%d "
              "pixels" % (base, w, h, big, bw, bh) in r.stderr, r.stderr)

        r = run(tool, "compare", base + ".png")
        check("one image only: exit 2", r.returncode == 2)
        check("one image only: the message",
              "give two images" in r.stderr, r.stderr)
        r = run(tool, "compare", base + ".png", base + ".png", "--dpi", "0")
        check("a bad --dpi: exit 2", r.returncode == 2)
        check("a bad --dpi: the message",
              "--dpi '0': give a number from 1 to 2400" in r.stderr,
              r.stderr)
        r = run(tool, "compare", base + ".png", base + ".png", "--frobnicate")
        check("an unknown option: exit 2", r.returncode == 2)
        check("an unknown option: the message",
              "unknown option --frobnicate" in r.stderr, r.stderr)
        nodir = os.path.join(tmp, "no", "such", "dir", "d.png")
        r = run(tool, "compare", moved + ".png", base + ".png",
                "--diff", nodir)
        check("an unwritable diff image: exit 2", r.returncode == 2)
        check("an unwritable diff image: the message",
              "cannot write " + nodir in r.stderr, r.stderr)
        check("an unwritable diff image: no file left",
              not os.path.exists(os.path.dirname(nodir)))

        r = run(tool, "help", "compare")
        check("help compare", r.returncode == 0 and
              "usage: curvefig compare A B" in r.stdout)
        r = run(tool, "compare", "--help")
        check("compare --help", r.returncode == 0 and
              "Exit status: 0 the same picture" in r.stdout)
    if failures:
        sys.exit("%d check(s) failed" % len(failures))


main()
