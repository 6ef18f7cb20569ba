#!/usr/bin/env python3
"""A lecturer's repository guarded with `curvefig test`.

    test_lecture.py TOOL

Makes a lecture-notes repository in a temporary directory, with three
figure scripts of its own (four figures), and guards it as docs/testing.md
tells: `curvefig test figures --references ref --update` writes the
references, `curvefig test figures --references ref` passes.  Then a
control point moved by about 1.4 pt must fail (exit 1) with a diff image
that marks the change in red and an HTML report naming that figure and no
other; --update lists it as changed and the others as unchanged; a removed
script fails the check and --update removes its references.  Bad input: a
missing reference directory, a missing reference, a script that fails, two
scripts defining one name, a reference directory that is a file.
"""
import os
import shutil
import struct
import subprocess
import sys
import tempfile
import zlib

SCRIPTS = {
    "cubic.lua": """
-- a cubic Bezier curve with its control polygon
local c = bezier{ {0, 0}, {1, 2.5}, {3.5, 2.5}, {4.5, 0.5} }
local f = figure{ name = "cubic", page = "fixed", width = "6cm", height = "4cm",
                  window = { -0.5, 5, -0.5, 3 } }
f:polygon(c)
f:curve(c)
f:points(c)
for i, p in ipairs(c:points()) do
  f:label(p, string.format("b_%d", i - 1), { place = "n" })
end
""",
    "spline.lua": """
-- a quadratic B-spline, and another one with its knots marked
local P = { {0, 0}, {1, 2}, {2.5, 2.5}, {3.5, 0.5}, {4.5, 1.5} }
local s = bspline{ degree = 2, knots = { 0, 0, 0, 0.3, 0.7, 1, 1, 1 },
                   points = P }
local f = figure{ name = "spline", width = "6cm", height = "4cm",
                  window = { -0.5, 5, -0.5, 3 } }
f:polygon(s)
f:curve(s)
f:points(s)
f:label(P[2], "P_1", { place = "nw" })
local t = bspline{ degree = 2, knots = { 0, 0, 0, 0.3, 0.7, 1, 1, 1 },
                   points = { {0, 1}, {1.5, 2.5}, {2.5, 0}, {3.5, 2},
                              {4.5, 1} } }
local g = figure{ name = "spline-knots", width = "6cm", height = "4cm",
                  window = { -0.5, 5, -0.5, 3 } }
g:curve(t)
g:knots(t)
""",
    "hull.lua": """
-- the convex hull of a control polygon
local c = bezier{ {0, 1}, {1.5, 2.8}, {2, 0}, {4, 2.5} }
local f = figure{ name = "hull", width = "6cm", height = "4cm",
                  window = { -0.5, 5, -0.5, 3 } }
f:hull(c:points())
f:polygon(c)
f:curve(c)
f:label({2, 1.2}, "$convex hull$")
""",
}
FIGURES = ["cubic", "hull", "spline", "spline-knots"]

failures = []


def check(what, cond, detail=""):
    if cond:
        print("ok  ", what)
    else:
        failures.append(what)
        print("FAIL", what, ("\n" + detail) if detail else "")


def read_png(path):
    """(width, height, rows of (r, g, b, a)) of an 8-bit RGB(A) PNG."""
    with open(path, "rb") as f:
        data = f.read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", path
    pos, idat = 8, b""
    while pos < len(data):
        n, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        if kind == b"IHDR":
            w, h, depth, colour, _, _, interlace = struct.unpack(
                ">IIBBBBB", body)
            assert depth == 8 and colour in (2, 6) and interlace == 0
        elif kind == b"IDAT":
            idat += body
        pos += 12 + n
    bpp = 4 if colour == 6 else 3
    raw, stride, prev, rows = zlib.decompress(idat), w * bpp, None, []
    for y in range(h):
        ftype = raw[y * (stride + 1)]
        line = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        up = prev if prev is not None else bytearray(stride)
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b = up[i]
            c = up[i - bpp] if i >= bpp else 0
            if ftype == 1:
                line[i] = (line[i] + a) & 255
            elif ftype == 2:
                line[i] = (line[i] + b) & 255
            elif ftype == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif ftype == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                pred = a if pa <= pb and pa <= pc else b if pb <= pc else c
                line[i] = (line[i] + pred) & 255
        rows.append([tuple(line[i:i + bpp]) + ((255,) if bpp == 3 else ())
                     for i in range(0, stride, bpp)])
        prev = line
    return w, h, rows


def red_pixels(path):
    _, _, rows = read_png(path)
    return sum(1 for row in rows for (r, g, b, a) in row
               if a == 255 and r == 255 and g == 0 and b == 0)


def main():
    tool = os.path.abspath(sys.argv[1])
    with tempfile.TemporaryDirectory() as repo:
        figs = os.path.join(repo, "figures")
        ref = os.path.join(repo, "ref")
        out = os.path.join(repo, "out")
        os.mkdir(figs)
        for name, text in SCRIPTS.items():
            with open(os.path.join(figs, name), "w", encoding="utf-8") as f:
                f.write(text)

        def test(*args):
            r = subprocess.run([tool, "test"] + list(args), cwd=repo,
                               capture_output=True, text=True)
            return r.returncode, r.stdout, r.stderr

        # a check before any reference exists is an error, not a pass
        rc, so, se = test("figures", "--references", "ref")
        check("no reference directory: exit 2", rc == 2, so + se)
        check("no reference directory: the message",
              "the reference directory ref does not exist; write the "
              "references first with --update" in se, se)

        # 1. the references written
        rc, so, se = test("figures", "--references", "ref", "-o", "out",
                          "--update")
        check("--update: exit 0", rc == 0, so + se)
        for n in FIGURES:
            check("--update: %s listed as new" % n,
                  "new:       %s\n" % n in so, so)
            for sub in ("", "nolabels"):
                p = os.path.join(ref, sub, n + ".png")
                check("--update: %s written" % p, os.path.isfile(p) and
                      read_png(p)[0] == read_png(
                          os.path.join(out, sub, n + ".png"))[0])
        check("--update: the count", "4 new, 0 changed, 0 unchanged, "
              "0 removed" in so, so)
        left = [f for d in (ref, os.path.join(ref, "nolabels"))
                for f in os.listdir(d) if not f.endswith(".png") and
                not os.path.isdir(os.path.join(d, f))]
        check("--update: no temporary file left", left == [], str(left))

        # 2. the check passes
        rc, so, se = test("figures", "--references", "ref", "-o", "out")
        check("check: exit 0", rc == 0, so + se)
        for n in FIGURES:
            check("check: %s passes" % n, "ok   %s\n" % n in so, so)
        check("check: the summary",
              "4 figure(s) of 3 script(s): 4 pass, 0 fail" in so, so)
        with open(os.path.join(out, "report.html"), encoding="utf-8") as f:
            check("check: the report says all pass",
                  "4 pass, 0 fail" in f.read())

        # an update without a change rewrites nothing
        stamps = {n: os.stat(os.path.join(ref, n + ".png")).st_mtime_ns
                  for n in FIGURES}
        rc, so, se = test("figures", "--references", "ref", "-o", "out",
                          "--update")
        check("unchanged --update: exit 0 and all unchanged", rc == 0 and
              "0 new, 0 changed, 4 unchanged, 0 removed" in so, so + se)
        check("unchanged --update: the files are left alone",
              all(os.stat(os.path.join(ref, n + ".png")).st_mtime_ns ==
                  stamps[n] for n in FIGURES))

        # 3. P_1 of the spline moved by 0.05 units: the window's 5.5 units
        # on 6 cm - 28 bp of margins are 25.8 bp per unit, so 1.3 pt, 2.6
        # pixels at 144 dpi
        path = os.path.join(figs, "spline.lua")
        with open(path, encoding="utf-8") as f:
            text = f.read()
        assert text.count("{1, 2}") == 1
        with open(path, "w", encoding="utf-8") as f:
            f.write(text.replace("{1, 2}", "{1.05, 2}"))
        rc, so, se = test("figures", "--references", "ref", "-o", "out")
        check("moved point: exit 1", rc == 1, so + se)
        check("moved point: spline fails",
              "FAIL spline (figures/spline.lua): its PNG against the "
              "reference ref/nolabels/spline.png, without labels: "
              "different: " in so, so)
        for n in ("cubic", "hull"):
            check("moved point: %s still passes" % n, "ok   %s\n" % n in so)
        diff = os.path.join(out, "failures",
                            "spline.reference-nolabels.diff.png")
        check("moved point: the diff image", os.path.isfile(diff))
        if os.path.isfile(diff):
            check("moved point: the diff image marks the change in red",
                  red_pixels(diff) > 10, str(red_pixels(diff)))
            w, h, _ = read_png(diff)
            check("moved point: the diff image has the figure's size",
                  (w, h) == read_png(os.path.join(ref, "spline.png"))[:2])
        with open(os.path.join(out, "report.html"), encoding="utf-8") as f:
            report = f.read()
        check("moved point: the report names spline",
              "<h2>spline</h2>" in report, report)
        check("moved point: the report shows the three images",
              'src="failures/spline.reference-nolabels.expected.png"' in
              report and
              'src="failures/spline.reference-nolabels.actual.png"' in
              report and
              'src="failures/spline.reference-nolabels.diff.png"' in report)
        check("moved point: the report has the numbers",
              "pixels differ (" in report)
        check("moved point: the report names no other figure",
              all("<h2>%s</h2>" % n not in report for n in
                  ("cubic", "hull", "spline-knots")))

        # the change accepted: listed as changed, the check passes again
        rc, so, se = test("figures", "--references", "ref", "-o", "out",
                          "--update")
        check("--update after the move: spline changed",
              rc == 0 and "changed:   spline\n" in so and
              "without labels: different: " in so, so + se)
        check("--update after the move: the others unchanged",
              "0 new, 1 changed, 3 unchanged, 0 removed" in so, so)
        rc, so, se = test("figures", "--references", "ref", "-o", "out")
        check("check after the update: exit 0", rc == 0, so + se)

        # a fixed page made wider: a failure saying both sizes, no diff image
        path = os.path.join(figs, "cubic.lua")
        with open(path, encoding="utf-8") as f:
            text = f.read()
        with open(path, "w", encoding="utf-8") as f:
            f.write(text.replace('width = "6cm"', 'width = "6.5cm"'))
        w, h, _ = read_png(os.path.join(ref, "cubic.png"))
        rc, so, se = test("figures", "--references", "ref", "-o", "out")
        check("a wider figure: exit 1", rc == 1, so + se)
        w2 = read_png(os.path.join(out, "cubic.png"))[0]
        check("a wider figure: both sizes in the message",
              "the sizes differ: %dx%d pixels, expected %dx%d" % (w2, h, w, h)
              in so, so)
        check("a wider figure: expected and actual kept, no diff",
              os.path.isfile(os.path.join(
                  out, "failures", "cubic.reference.expected.png")) and
              not os.path.exists(os.path.join(
                  out, "failures", "cubic.reference.diff.png")))
        with open(path, "w", encoding="utf-8") as f:
            f.write(text)

        # a single script checks its figures only
        rc, so, se = test("figures/hull.lua", "--references", "ref", "-o",
                          "out")
        check("one script: exit 0", rc == 0 and "1 figure(s) of 1 script(s)"
              in so, so + se)

        # a removed script: its references have no figure
        shutil.move(os.path.join(figs, "hull.lua"),
                    os.path.join(repo, "hull.lua"))
        rc, so, se = test("figures", "--references", "ref", "-o", "out")
        check("removed figure: exit 1", rc == 1, so + se)
        check("removed figure: the message",
              "the reference ref/hull.png has no figure any more" in so, so)
        rc, so, se = test("figures", "--references", "ref", "-o", "out",
                          "--update")
        check("removed figure: --update removes it",
              rc == 0 and "removed:   hull" in so and
              not os.path.exists(os.path.join(ref, "hull.png")) and
              not os.path.exists(os.path.join(ref, "nolabels", "hull.png")),
              so + se)
        shutil.move(os.path.join(repo, "hull.lua"),
                    os.path.join(figs, "hull.lua"))
        rc, so, se = test("figures", "--references", "ref", "-o", "out")
        check("a new figure without a reference: exit 1", rc == 1 and
              "no reference image ref/hull.png (write it with --update)"
              in so, so + se)
        test("figures", "--references", "ref", "-o", "out", "--update")

        # a script that fails: an error naming the file and line, and no
        # reference written for it
        with open(os.path.join(figs, "broken.lua"), "w") as f:
            f.write('local f = figure{ name = "broken", width = "3cm",\n'
                    '  height = "2cm" }\nf:curve(nil)\n')
        rc, so, se = test("figures", "--references", "ref", "-o", "out",
                          "--update")
        check("a failing script: exit 2", rc == 2, so + se)
        check("a failing script: file and line in the message",
              "broken.lua:3:" in se, se)
        check("a failing script: no reference written for it",
              not os.path.exists(os.path.join(ref, "broken.png")))
        check("a failing script: the other references kept",
              all(os.path.isfile(os.path.join(ref, n + ".png"))
                  for n in FIGURES))
        os.remove(os.path.join(figs, "broken.lua"))

        # two scripts defining one figure name
        with open(os.path.join(figs, "twin.lua"), "w") as f:
            f.write('local f = figure{ name = "cubic", width = "3cm",\n'
                    '  height = "2cm" }\nf:curve(bezier{ {0,0}, {1,1} })\n')
        rc, so, se = test("figures", "--references", "ref", "-o", "out")
        check("one name twice: exit 2", rc == 2 and
              "the figure 'cubic' is defined by figures/cubic.lua and by "
              "figures/twin.lua" in se, se)
        os.remove(os.path.join(figs, "twin.lua"))

        # a reference that is not a PNG any more: an error naming it
        bad = os.path.join(ref, "nolabels", "cubic.png")
        with open(bad, "wb") as f:
            f.write(b"\x89PNG\r\n\x1a\n broken")
        rc, so, se = test("figures", "--references", "ref", "-o", "out")
        check("a corrupt reference: exit 2", rc == 2, so + se)
        check("a corrupt reference: the message names it",
              "ref/nolabels/cubic.png: not a readable PNG file" in so, so)
        rc, so, se = test("figures", "--references", "ref", "-o", "out",
                          "--update")
        check("a corrupt reference: --update replaces it", rc == 0 and
              "changed:   cubic" in so and
              "without labels: the old reference was unreadable" in so,
              so + se)

        # an output directory that cannot be made
        with open(os.path.join(repo, "ref-file"), "w") as f:
            f.write("x")
        rc, so, se = test("figures", "--references", "ref", "-o",
                          "ref-file/out")
        check("an output directory that cannot be made: exit 2", rc == 2 and
              "cannot create the output directory" in se, se)

        # usage errors
        rc, so, se = test("figures")
        check("no --references: exit 2", rc == 2 and
              "--references DIR" in se, se)
        rc, so, se = test("nowhere", "--references", "ref")
        check("a missing operand: exit 2", rc == 2 and
              "cannot read nowhere" in se, se)
        rc, so, se = test("figures", "--references", "ref-file")
        check("a reference directory that is a file: exit 2", rc == 2 and
              "ref-file is not a directory" in se, se)
        r = subprocess.run([tool, "help", "test"], capture_output=True,
                           text=True)
        check("help test", r.returncode == 0 and
              "usage: curvefig test" in r.stdout)
    if failures:
        sys.exit("%d check(s) failed" % len(failures))


main()
