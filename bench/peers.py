#!/usr/bin/env python3
"""The two figures of the peer comparison, timed side by side in one run.

    peers.py TOOL SOURCE_DIR [--pairs N] [--baseline OLD_TOOL]

For orazem-decasteljau and markova-2.17: curvefig's PDF (`TOOL render
figures/NAME.lua -f pdf --only NAME`), the same figure as MetaPost
(bench/peers/NAME.mp, `mpost`, EPS with its labels set by TeX, the
labels' .mpx removed before each run as after an edit) and as TikZ
(bench/peers/NAME.tex, `pdflatex`, PDF), copied to a scratch directory,
and an empty program (`true`: what any process costs here).  Each round
runs them in turn (the order rotates), N rounds (default 7) after one
warm-up round; the CPU time (user + system) of each process and its
children, started by posix_spawn (bench/cputime.py).  One JSON
line per figure: the medians and how many times faster curvefig is
(targets of issue #28: >= 10x MetaPost, >= 60x TikZ).  A peer that is not
installed is left out; exit status 77 (skipped) when neither is.  With
--baseline, another build's `curvefig` (OLD_TOOL) renders the same PDF
in the same rounds (the two trading places every other round, so that
each follows the other and the empty program equally often), and the
line adds its median and the median of the per-round ratios TOOL /
OLD_TOOL (a before/after in one run).
"""
import json
import os
import shutil
import statistics
import sys
import tempfile

from cputime import cpu_of, have_pdflatex, pdflatex

FIGURES = ("orazem-decasteljau", "markova-2.17")


def main(argv):
    if len(argv) < 3:
        sys.stderr.write(__doc__)
        return 2
    tool, src = os.path.abspath(argv[1]), os.path.abspath(argv[2])
    pairs = int(argv[argv.index("--pairs") + 1]) if "--pairs" in argv else 7
    baseline = (os.path.abspath(argv[argv.index("--baseline") + 1])
                if "--baseline" in argv else None)
    peers = {}
    if shutil.which("mpost") and shutil.which("tex"):
        # the .mpx of the labels removed first: a figure just edited
        peers["metapost_eps"] = lambda name: [
            "sh", "-c", "rm -f %s.mpx && exec mpost -interaction=batchmode "
            "%s.mp" % (name, name)]
    if have_pdflatex():
        peers["tikz_pdf"] = lambda name: pdflatex(name + ".tex")
    if not peers:
        print("peers: neither mpost nor pdflatex is installed: skipped")
        return 77
    here = os.getcwd()
    with tempfile.TemporaryDirectory() as tmp:
        os.chdir(tmp)  # the peers write beside their sources
        try:
            run_rounds(tool, src, tmp, pairs, baseline, peers)
        finally:
            os.chdir(here)
    return 0


def run_rounds(tool, src, tmp, pairs, baseline, peers):
    """The rounds of each figure, run in tmp; one JSON line each."""
    for name in FIGURES:
        for ext in (".mp", ".tex"):
            shutil.copy(os.path.join(src, "bench", "peers", name + ext),
                        tmp)
        cmds = {"curvefig_pdf": [tool, "render",
                                 os.path.join(src, "figures",
                                              name + ".lua"),
                                 "-o", tmp, "-f", "pdf", "--only", name]}
        if baseline is not None:
            cmds["baseline_pdf"] = [baseline] + cmds["curvefig_pdf"][1:]
        for k, make in peers.items():
            cmds[k] = make(name)
        # what any process costs here, measured the same way
        cmds["empty_program"] = ["true"]
        times = {k: [] for k in cmds}
        keys = list(cmds)
        for r in range(pairs + 1):
            ring = list(keys)
            if baseline is not None and r % 2 == 1:
                # the two builds trade places every other round: a run
                # after a peer's (pdflatex leaves the caches cold) costs
                # more than one after the other build's, so with a fixed
                # ring the build after the other was always the warmer
                # one (the same binary beside itself: 1.04-1.07)
                i = ring.index("curvefig_pdf")
                j = ring.index("baseline_pdf")
                ring[i], ring[j] = ring[j], ring[i]
            order = ring[r % len(ring):] + ring[:r % len(ring)]
            for k in order:
                t = cpu_of(cmds[k])
                if r > 0:
                    times[k].append(t)
        med = {k: statistics.median(v) for k, v in times.items()}
        out = {"figure": name, "rounds": pairs}
        out.update({k + "_cpu_s": round(v, 4) for k, v in med.items()})
        for k in peers:
            out["times_faster_than_" + k] = round(
                med[k] / med["curvefig_pdf"], 1)
        if baseline is not None:
            out["ratio_to_baseline"] = round(statistics.median(
                a / b for a, b in zip(times["curvefig_pdf"],
                                      times["baseline_pdf"])), 3)
        print(json.dumps(out), flush=True)


if __name__ == "__main__":
    try:
        sys.exit(main(sys.argv))
    except RuntimeError as e:
        sys.stderr.write("peers: %s\n" % e)
        sys.exit(1)
