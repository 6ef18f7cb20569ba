#!/usr/bin/env python3
"""`curvefig test` checks every overlay step.

    test_steps.py TOOL

A figure with three overlay steps is guarded with `curvefig test
--update` (its references: the figure and NAME-1, NAME-2, NAME-3 with and
without labels), and passes `curvefig test`.  Then an element shown on
step 1 only is moved: the last step, which NAME.png shows, is unchanged,
yet the check must fail (exit 1), name step 1 and no other step, and
--update must list the figure as changed in step 1.
"""
import os
import subprocess
import sys
import tempfile

SCRIPT = """
local c = bezier{ {0, 0}, {1, 2.5}, {3.5, 2.5}, {4.5, 0.5} }
local f = figure{ name = "steps", width = "6cm", height = "4cm",
                  window = { -0.5, 5, -0.5, 3 } }
f:polygon(c)
f:points({ %s }, { visible = "1", color = "red" })
f:label({ 2, 1 }, "b_0", { visible = "2" })
f:curve(c, { visible = "3" })
"""

failures = []


def check(what, cond, detail=""):
    if cond:
        print("ok  ", what)
    else:
        failures.append(what)
        print("FAIL", what, ("\n" + detail) if detail else "")


def run(tool, *args):
    p = subprocess.run([tool] + list(args), capture_output=True, text=True)
    return p.returncode, p.stdout + p.stderr


def main():
    tool = os.path.abspath(sys.argv[1])
    with tempfile.TemporaryDirectory() as d:
        script = os.path.join(d, "steps.lua")
        ref, out = os.path.join(d, "ref"), os.path.join(d, "out")
        with open(script, "w") as f:
            f.write(SCRIPT % "{1, 1}")
        rc, text = run(tool, "test", script, "--references", ref, "-o", out,
                       "--update")
        check("--update writes the references", rc == 0, text)
        for k in (1, 2, 3):
            for sub in ("", "nolabels"):
                path = os.path.join(ref, sub, "steps-%d.png" % k)
                check("reference %s" % os.path.relpath(path, d),
                      os.path.exists(path))
        rc, text = run(tool, "test", script, "--references", ref, "-o", out)
        check("unchanged: passes", rc == 0 and "ok   steps (3 steps)" in text,
              text)
        # the red point of step 1 moves by 0.3 (about 9 bp at this scale)
        with open(script, "w") as f:
            f.write(SCRIPT % "{1.3, 1}")
        rc, text = run(tool, "test", script, "--references", ref, "-o", out)
        check("a change on step 1 only fails", rc == 1, text)
        check("the failure names step 1",
              "FAIL steps-1 " in text and "step 1: its PNG" in text, text)
        check("and no other step",
              "steps-2" not in text and "steps-3" not in text
              and "FAIL steps " not in text, text)
        rc, text = run(tool, "test", script, "--references", ref, "-o", out,
                       "--update")
        check("--update lists step 1 as changed",
              rc == 0 and "changed:   steps" in text
              and "steps: 1\n" in text, text)
    if failures:
        print("%d failure(s)" % len(failures))
        sys.exit(1)


main()
