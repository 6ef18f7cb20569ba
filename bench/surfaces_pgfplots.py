#!/usr/bin/env python3
"""The whole surface chapter beside one pgfplots surface plot.

    surfaces_pgfplots.py TOOL SOURCE_DIR [--rounds N]

curvefig: every script of figures/surfaces/ rendered to PDF (`TOOL render
SCRIPT -f pdf`, one process per script, as `ninja figures` runs them), the
CPU time (user + system) of the processes summed (started by posix_spawn:
bench/cputime.py); pgfplots: the bicubic patch of surfaces-bezier-patch
as one `surf` plot of 25 x 25 samples
(bench/peers/surface-patch-pgfplots.tex, `pdflatex`).  N rounds (default
5) after one warm-up, the two in turn; one JSON line with the medians and
the ratio (issue #30: the chapter in less time than the one plot).  Exit
status 77 (skipped) without pdflatex or pgfplots.
"""
import glob
import json
import os
import shutil
import statistics
import sys
import tempfile

from cputime import cpu_of, have_pdflatex, pdflatex


def main(argv):
    if len(argv) < 3:
        sys.stderr.write(__doc__)
        return 2
    tool, src = os.path.abspath(argv[1]), os.path.abspath(argv[2])
    rounds = int(argv[argv.index("--rounds") + 1]) if "--rounds" in argv else 5
    if not have_pdflatex("pgfplots.sty"):
        print("surfaces_pgfplots: pdflatex with pgfplots not found: skipped")
        return 77
    scripts = sorted(glob.glob(os.path.join(src, "figures", "surfaces",
                                            "*.lua")))
    with tempfile.TemporaryDirectory() as tmp:
        shutil.copy(os.path.join(src, "bench", "peers",
                                 "surface-patch-pgfplots.tex"), tmp)

        def chapter():
            return sum(cpu_of([tool, "render", s, "-o", tmp, "-f", "pdf"],
                              tmp) for s in scripts)

        def pgfplots():
            return cpu_of(pdflatex("surface-patch-pgfplots.tex"), tmp)

        chapter()
        pgfplots()
        ours, theirs = [], []
        for _ in range(rounds):
            ours.append(chapter())
            theirs.append(pgfplots())
    a, b = statistics.median(ours), statistics.median(theirs)
    print(json.dumps({"benchmark": "surface-chapter-vs-pgfplots",
                      "scripts": len(scripts), "rounds": rounds,
                      "curvefig_chapter_pdf_s": round(a, 3),
                      "pgfplots_one_surface_s": round(b, 3),
                      "ratio": round(b / a, 2) if a > 0 else None}))
    return 0 if a < b else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
