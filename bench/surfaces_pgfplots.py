#!/usr/bin/env python3
"""The whole surface chapter beside one pgfplots surface plot.

    surfaces_pgfplots.py TOOL SOURCE_DIR [--rounds N]

curvefig: every script of figures/surfaces/ rendered to PDF (`TOOL render
SCRIPT -f pdf`, one process per script, as `ninja figures` runs them), the
CPU time (user + system) of the processes summed; pgfplots: the bicubic
patch of surfaces-bezier-patch as one `surf` plot of 25 x 25 samples
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
import subprocess
import sys
import tempfile


def cpu_of(argv, cwd):
    """Run argv in cwd (output discarded); CPU seconds of it and children."""
    pid = os.fork()
    if pid == 0:
        try:
            os.chdir(cwd)
            fd = os.open(os.devnull, os.O_RDWR)
            for k in (0, 1, 2):
                os.dup2(fd, k)
            os.execvp(argv[0], argv)
        finally:
            os._exit(127)
    _, status, ru = os.wait4(pid, 0)
    if status != 0:
        raise RuntimeError("failed (status %d): %s" % (status, " ".join(argv)))
    return ru.ru_utime + ru.ru_stime


def main(argv):
    if len(argv) < 3:
        sys.stderr.write(__doc__)
        return 2
    tool, src = os.path.abspath(argv[1]), os.path.abspath(argv[2])
    rounds = int(argv[argv.index("--rounds") + 1]) if "--rounds" in argv else 5
    if not shutil.which("pdflatex") or subprocess.run(
            ["kpsewhich", "pgfplots.sty"], stdout=subprocess.PIPE,
            check=False).stdout.strip() == b"":
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
            return cpu_of(["pdflatex", "-interaction=batchmode",
                           "-halt-on-error", "surface-patch-pgfplots.tex"],
                          tmp)

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
