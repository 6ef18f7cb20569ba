#!/usr/bin/env python3
"""The tool's cost against another build of it (another commit), in one run.

    startup_compare.py NEW_TOOL OLD_TOOL FIGURES_DIR [--pairs N] [--sets N]
    startup_compare.py NEW_TOOL --commit REV [--source DIR] FIGURES_DIR ...

OLD_TOOL is the `curvefig` of the other build.  With --commit REV the
script builds that commit itself: `git archive REV` of the source
repository (--source, default: this file's repository) unpacked into
/tmp/curvefig-REV, `meson setup` and `ninja render/tool/curvefig` there
(a build of its own, outside the source tree; it needs the same
packages).  FIGURES_DIR is the set of course scripts to render: give the
old commit's figures/ (e.g. /tmp/curvefig-REV/figures) so that both tools
render the same scripts.

Measured, as CPU time (user + system) of the tool's processes:
  minimal   a figure with one polyline and no label, `render -f pdf`:
            --pairs pairs of runs (default 41), old and new alternating
            (which goes first alternates too), one process each;
  course    every script of FIGURES_DIR rendered in svg, pdf and png, one
            process per script: --sets pairs of whole sets (default 5).
Prints one JSON line per measurement with the medians and the median of
the paired ratios new / old.  The targets of issue #28 against commit
1f9e659: minimal <= 0.6, course <= 0.9.  Both tools are timed as copies
(made here, in a temporary directory, with the libraries their $ORIGIN
run path finds): the kernel caches a file the linker has just
written, or one read back from disk, in smaller pieces than one written
whole, and that alone made the same program 0.15-0.25 ms slower per start
here.  Exit status 0, or 1 when a render fails.
"""
import json
import os
import shutil
import statistics
import subprocess
import sys
import tempfile

from cputime import cpu_of

MINIMAL = """local f = figure{ name = "minimal", width = "4cm", height = "3cm" }
f:polyline({ {0, 0}, {1, 1}, {2, 0} })
"""


def build_commit(rev, source):
    out = os.path.join(tempfile.gettempdir(), "curvefig-" + rev)
    tool = os.path.join(out, "build", "render", "tool", "curvefig")
    if os.access(tool, os.X_OK):
        return tool, out
    os.makedirs(out, exist_ok=True)
    archive = subprocess.run(["git", "-C", source, "archive", rev],
                             check=True, capture_output=True).stdout
    subprocess.run(["tar", "-x", "-C", out], input=archive, check=True)
    subprocess.run(["meson", "setup", "build"], cwd=out, check=True,
                   stdout=subprocess.DEVNULL)
    subprocess.run(["ninja", "-C", "build", "render/tool/curvefig"],
                   cwd=out, check=True, stdout=subprocess.DEVNULL)
    return tool, out


def timed_copy(tool, root):
    """A copy of tool under root (see above), with copies of the shared
    libraries of the directories its $ORIGIN run path names; tool itself
    where that is its own directory."""
    dynamic = subprocess.run(["readelf", "-dW", tool], capture_output=True,
                             text=True).stdout
    paths = []
    for line in dynamic.splitlines():
        if "(RUNPATH)" in line or "(RPATH)" in line:
            paths += line[line.index("[") + 1:line.rindex("]")].split(":")
    rels = [os.path.normpath(p[len("$ORIGIN"):].lstrip("/") or ".")
            for p in paths if p.startswith("$ORIGIN")]
    if "." in rels:
        return tool
    depth = max([r.split(os.sep).count("..") for r in rels] + [0])
    where = os.path.join(root, *(["d"] * depth))
    os.makedirs(where)
    for r in rels:
        there = os.path.normpath(os.path.join(os.path.dirname(tool), r))
        here = os.path.normpath(os.path.join(where, r))
        os.makedirs(here, exist_ok=True)
        for f in os.listdir(there) if os.path.isdir(there) else []:
            if (".so" in f and os.path.isfile(os.path.join(there, f)) and
                    not os.path.lexists(os.path.join(here, f))):
                shutil.copy(os.path.join(there, f), here)
    return shutil.copy(tool, where)


def paired(name, runs):
    """runs: [(new, old)]: medians and the median paired ratio."""
    new = [a for a, _ in runs]
    old = [b for _, b in runs]
    ratio = statistics.median(a / b for a, b in runs if b > 0)
    print(json.dumps({"measurement": name, "pairs": len(runs),
                      "new_cpu_s": round(statistics.median(new), 5),
                      "old_cpu_s": round(statistics.median(old), 5),
                      "ratio_new_old": round(ratio, 3)}), flush=True)


def main(argv):
    args, opts, i = [], {"--pairs": "41", "--sets": "5"}, 1
    while i < len(argv):
        if argv[i] in ("--pairs", "--sets", "--commit", "--source"):
            opts[argv[i]] = argv[i + 1]
            i += 2
        else:
            args.append(argv[i])
            i += 1
    if "--commit" in opts and len(args) == 2:
        source = opts.get("--source",
                          os.path.dirname(os.path.dirname(os.path.abspath(
                              __file__))))
        try:
            old_tool, _ = build_commit(opts["--commit"], source)
        except (OSError, subprocess.CalledProcessError) as e:
            # not a git checkout of the project, or the commit does not build
            sys.stderr.write("startup_compare: cannot build commit %s "
                             "(%s): skipped\n" % (opts["--commit"], e))
            return 77
        new_tool, figures = args
    elif len(args) == 3:
        new_tool, old_tool, figures = args
    else:
        sys.stderr.write(__doc__)
        return 2
    new_tool, old_tool = os.path.abspath(new_tool), os.path.abspath(old_tool)
    scripts = sorted(os.path.join(figures, f) for f in os.listdir(figures)
                     if f.endswith(".lua"))
    with tempfile.TemporaryDirectory() as tmp:
        new_tool = timed_copy(new_tool, os.path.join(tmp, "new-tool"))
        old_tool = timed_copy(old_tool, os.path.join(tmp, "old-tool"))
        minimal = os.path.join(tmp, "minimal.lua")
        with open(minimal, "w") as f:
            f.write(MINIMAL)

        def render(tool, script, formats, out):
            return cpu_of([tool, "render", script, "-o", out, "-f", formats])

        outs = {t: os.path.join(tmp, k) for t, k in ((new_tool, "new"),
                                                      (old_tool, "old"))}
        for t in outs:
            os.makedirs(outs[t], exist_ok=True)
            render(t, minimal, "pdf", outs[t])   # warm the caches
        runs = []
        for k in range(int(opts["--pairs"])):
            order = (new_tool, old_tool) if k % 2 == 0 else (old_tool, new_tool)
            got = {t: render(t, minimal, "pdf", outs[t]) for t in order}
            runs.append((got[new_tool], got[old_tool]))
        paired("minimal render -f pdf", runs)
        runs = []
        for k in range(int(opts["--sets"])):
            order = (new_tool, old_tool) if k % 2 == 0 else (old_tool, new_tool)
            got = {t: sum(render(t, s, "svg,pdf,png", outs[t]) for s in scripts)
                   for t in order}
            runs.append((got[new_tool], got[old_tool]))
        if runs:
            paired("course set (%d scripts, svg+pdf+png)" % len(scripts),
                   runs)
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main(sys.argv))
    except (RuntimeError, subprocess.CalledProcessError) as e:
        sys.stderr.write("startup_compare: %s\n" % e)
        sys.exit(1)
