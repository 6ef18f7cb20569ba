"""Evaluation from Python beside C and scipy, in one run (issue #34's
targets): 10^6 parameters on a cubic Bézier curve and a cubic B-spline,
medians of RUNS runs in ns per point,

  - curvefig from Python within 1.5 times the C benchmark per point
    (bench/eval_points.c: the same curves through the batch evaluators,
    into one output buffer reused: so Python with eval(u, out=buffer);
    eval(u), which has numpy allocate 16 MB each time and the kernel map
    its pages in, is shown beside it);
  - at least 5 times faster than scipy's BSpline.__call__ on the same
    B-spline (and BPoly.__call__ on the same Bézier curve, shown only),
    both allocating their result.

    python_eval.py EVAL_POINTS_PROGRAM [RUNS]

with PYTHONPATH at the built package (python/meson.build runs it as a
benchmark: meson test --benchmark).  Exit status 1 when a target is
missed."""

import json
import subprocess
import sys
import time

import numpy as np

import curvefig

N = 1_000_000
COUNT = 20


def median_ns(f, runs):
    ts = []
    for _ in range(runs):
        t0 = time.perf_counter()
        f()
        ts.append(time.perf_counter() - t0)
    ts.sort()
    return ts[len(ts) // 2] / N * 1e9


def main():
    prog = sys.argv[1]
    runs = int(sys.argv[2]) if len(sys.argv) > 2 else 9
    c_side = json.loads(subprocess.run([prog, str(N), str(runs), str(COUNT)],
                                       capture_output=True, text=True,
                                       check=True).stdout)
    u = np.linspace(0.0, 1.0, N)
    bz = curvefig.Bezier([[0, 0], [1, 2], [3, 2], [4, 0]])
    P = np.array([[i, np.sin(i)] for i in range(COUNT)])
    bs = curvefig.BSpline(3, None, P)
    rows = {"bezier": {"c": c_side["bezier_ns"]},
            "bspline": {"c": c_side["bspline_ns"]}}
    buf = np.empty((N, 2))
    rows["bezier"]["python"] = median_ns(lambda: bz.eval(u, out=buf), runs)
    rows["bspline"]["python"] = median_ns(lambda: bs.eval(u, out=buf), runs)
    rows["bezier"]["python_new"] = median_ns(lambda: bz.eval(u), runs)
    rows["bspline"]["python_new"] = median_ns(lambda: bs.eval(u), runs)
    try:
        from scipy.interpolate import BPoly, BSpline
        sb = BSpline(bs.knots, bs.points, 3)
        sp = BPoly(bz.points[:, None, :], [0.0, 1.0])
        assert np.max(np.abs(sb(u[::997]) - bs.eval(u[::997]))) < 1e-13
        rows["bspline"]["scipy"] = median_ns(lambda: sb(u), runs)
        rows["bezier"]["scipy"] = median_ns(lambda: sp(u), runs)
    except ImportError:
        print("scipy is missing: no comparison with it (Debian: "
              "python3-scipy)")
    ok = True
    print("10^6 parameters, median of %d runs, ns per point" % runs)
    print("%-8s %8s %8s %10s %8s %11s %15s" % (
        "curve", "C", "Python", "Python new", "scipy", "Python / C",
        "scipy / Python"))
    for name, r in rows.items():
        ratio = r["python"] / r["c"]
        sc = r.get("scipy")
        speedup = sc / r["python_new"] if sc else float("nan")
        print("%-8s %8.2f %8.2f %10.2f %8s %11.2f %15s" % (
            name, r["c"], r["python"], r["python_new"],
            "%.2f" % sc if sc else "-", ratio,
            "%.1f" % speedup if sc else "-"))
        if ratio > 1.5:
            print("MISSED: %s from Python is %.2f times C (target <= 1.5)"
                  % (name, ratio))
            ok = False
        if name == "bspline" and sc and speedup < 5.0:
            print("MISSED: scipy's BSpline is only %.1f times slower "
                  "(target >= 5)" % speedup)
            ok = False
    print(json.dumps(rows))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
