#!/usr/bin/env python3
"""The pixel suite must see a changed figure.

    expect-change.py TOOL REFDIR OUTDIR SCRIPT FIGURE

Runs `TOOL test SCRIPT --references REFDIR -o OUTDIR` on a script whose
figure FIGURE was changed on purpose and passes only when the run fails as
a difference (exit status 1, not an error), the strict label-free
comparison with the reference is among the failures, and the diff image
and the HTML report naming the figure were written.
"""
import os
import subprocess
import sys


def main():
    tool, refdir, outdir, script, figure = sys.argv[1:6]
    run = subprocess.run([tool, "test", script, "--references", refdir,
                          "-o", outdir], capture_output=True, text=True)
    sys.stdout.write(run.stdout)
    sys.stderr.write(run.stderr)
    problems = []
    if run.returncode != 1:
        problems.append("exit status %d, expected 1" % run.returncode)
    strict = [l for l in run.stdout.splitlines()
              if l.startswith("FAIL " + figure + " ")
              and "against the reference" in l and "without labels" in l]
    if not strict:
        problems.append("no failure of the label-free reference comparison")
    diff = os.path.join(outdir, "failures",
                        figure + ".reference-nolabels.diff.png")
    if not os.path.isfile(diff):
        problems.append("no diff image " + diff)
    report = os.path.join(outdir, "report.html")
    if not os.path.isfile(report) or figure not in open(report).read():
        problems.append("no report naming %s in %s" % (figure, report))
    if problems:
        sys.exit("the perturbed figure was NOT detected as it should be: "
                 + "; ".join(problems))
    print("perturbation detected, as expected")


main()
