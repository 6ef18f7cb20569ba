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
warm-up round (two with --baseline, whose rounds go in pairs: N even); the CPU time (user + system) of each process and its
children, started by posix_spawn (bench/cputime.py).  One JSON
line per figure: the medians and how many times faster curvefig is
(targets of issue #28: >= 10x MetaPost, >= 60x TikZ).  A peer that is not
installed is left out; exit status 77 (skipped) when neither is.  With
--baseline, another build's `curvefig` (OLD_TOOL) renders the same PDF
in the same rounds (the two side by side, first one then the other, as
a run after a peer's finds colder caches than one after the other
build's), and the line adds its median and the median over pairs of
rounds of the geometric mean of the two rounds' ratios TOOL / OLD_TOOL
(a before/after in one run).
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
        keys = [k for k in cmds if k != "baseline_pdf"]
        warm = 2 if baseline is not None else 1
        for r in range(pairs + warm):
            # the ring turns every round (every pair of rounds with a
            # baseline), so that each command follows each other one
            turn = (r // 2 if baseline is not None else r) % len(keys)
            order = keys[turn:] + keys[:turn]
            if baseline is not None:
                # the two builds run side by side, right after curvefig's
                # place in the ring, in turns: the second of the two finds
                # the caches the first warmed (after a peer's run they are
                # cold), so each round's ratio leans one way and the next
                # round's the other by as much (in a fixed order the same
                # binary beside itself measured 1.13-1.52)
                i = order.index("curvefig_pdf")
                pair = ["curvefig_pdf", "baseline_pdf"]
                order[i:i + 1] = pair if r % 2 == 1 else pair[::-1]
            for k in order:
                t = cpu_of(cmds[k])
                if r >= warm:   # warm-up rounds first (a pair of them)
                    times[k].append(t)
        med = {k: statistics.median(v) for k, v in times.items()}
        out = {"figure": name, "rounds": pairs}
        out.update({k + "_cpu_s": round(v, 4) for k, v in med.items()})
        for k in peers:
            out["times_faster_than_" + k] = round(
                med[k] / med["curvefig_pdf"], 1)
        if baseline is not None:
            # per pair of rounds (one of each order), the geometric mean
            # of the two rounds' ratios: the order's lean cancels
            c, b = times["curvefig_pdf"], times["baseline_pdf"]
            out["ratio_to_baseline"] = round(statistics.median(
                (c[k] / b[k] * c[k + 1] / b[k + 1]) ** 0.5
                for k in range(0, len(c) - 1, 2)), 3)
        print(json.dumps(out), flush=True)


if __name__ == "__main__":
    try:
        sys.exit(main(sys.argv))
    except RuntimeError as e:
        sys.stderr.write("peers: %s\n" % e)
        sys.exit(1)
