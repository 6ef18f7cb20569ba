"""Triangular Bézier patches (curvefig.BezierTriangle) against exact
rational arithmetic: the Bernstein sum, derivatives as blossoms, the
subdivided and elevated patches, and bad input."""

from fractions import Fraction
from math import factorial

import numpy as np
import pytest

import curvefig
from conftest import exact_values, run_lua

EPS = np.finfo(float).eps

# degree 3 in R^3, 10 points in the order b_300, b_210, b_201, b_120, ...
P3 = [[0, 0, 0], [1, 0, 1], [0, 1, 2], [2, 0, -1], [1, 1, 3], [0, 2, 1],
      [3, 0, 0], [2, 1, 1], [1, 2, -2], [0, 3, 0]]
W3 = [1, 2, 1, 3, 1, 2, 1, 1, 4, 1]
UV = [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (0.25, 0.5), (0.1, 0.7),
      (1 / 3, 1 / 3), (0.6, 0.05), (0.0, 0.4)]


def indices(n):
    """(i, j, k) in the header's order."""
    return [(i, j, n - i - j) for i in range(n, -1, -1)
            for j in range(n - i, -1, -1)]


def patch_exact(P, W, u, v):
    """T(u, v, w) by the Bernstein sum in exact rationals."""
    n = round((np.sqrt(8 * len(P) + 1) - 3) / 2)
    u, v = Fraction(u), Fraction(v)
    w = 1 - u - v
    W = W or [1] * len(P)
    num = [Fraction(0)] * len(P[0])
    den = Fraction(0)
    for (i, j, k), p, wt in zip(indices(n), P, W):
        b = Fraction(factorial(n), factorial(i) * factorial(j)
                     * factorial(k)) * u**i * v**j * w**k * Fraction(wt)
        num = [a + b * Fraction(x) for a, x in zip(num, p)]
        den += b
    return [a / den for a in num]


def blossom_exact(P, args):
    """The blossom b[args[0], ..., args[n-1]] of a polynomial patch, each
    argument barycentric (exact); D_d^k T = n!/(n-k)! b[d^k, p^(n-k)]."""
    n = len(args)
    pts = {ijk: [Fraction(x) for x in p] for ijk, p in zip(indices(n), P)}
    for level, (a, b, c) in enumerate(args, 1):
        m = n - level
        pts = {(i, j, k): [a * x + b * y + c * z for x, y, z in zip(
            pts[(i + 1, j, k)], pts[(i, j + 1, k)], pts[(i, j, k + 1)])]
               for (i, j, k) in indices(m)}
    return pts[(0, 0, 0)]


def close(a, b, tol=8 * EPS):
    a = np.asarray(a, float)
    b = np.asarray([[float(x) for x in r] for r in b] if np.ndim(b) > 1
                   else [float(x) for x in b])
    return np.max(np.abs(a - b)) <= tol * max(1.0, np.max(np.abs(b)))


@pytest.fixture
def cubic():
    return curvefig.BezierTriangle(np.array(P3, float))


@pytest.fixture
def rational():
    return curvefig.BezierTriangle(np.array(P3, float), weights=W3)


def test_eval_exact(cubic, rational):
    assert cubic.degree == 3 and cubic.dim == 3 and not cubic.is_rational
    assert rational.is_rational
    assert np.array_equal(rational.points, P3)
    assert np.array_equal(rational.weights, W3)
    for u, v in UV:
        assert close(cubic.eval(u, v), patch_exact(P3, None, u, v))
        assert close(rational.eval(u, v), patch_exact(P3, W3, u, v))
    # u and v broadcast: (4, 1) against (3,) gives (4, 3, dim)
    u = np.array([0.0, 0.1, 0.2, 0.3])[:, None]
    v = np.array([0.0, 0.3, 0.6])
    got = cubic.eval(u, v)
    assert got.shape == (4, 3, 3)
    assert close(got[2, 1], patch_exact(P3, None, 0.2, 0.3))


def test_decasteljau_levels(cubic):
    u, v = 0.25, 0.5
    levels = cubic.decasteljau(u, v)
    assert [lev.shape for lev in levels] == [(10, 3), (6, 3), (3, 3), (1, 3)]
    assert np.array_equal(levels[0], P3)
    # level 1 point b^1_ijk = u b_(i+1)jk + v b_i(j+1)k + w b_ij(k+1)
    bary = (Fraction(u), Fraction(v), 1 - Fraction(u) - Fraction(v))
    one = {ijk: p for ijk, p in zip(indices(3), P3)}
    want = [[bary[0] * one[(i + 1, j, k)][c] + bary[1] * one[(i, j + 1, k)][c]
             + bary[2] * one[(i, j, k + 1)][c] for c in range(3)]
            for (i, j, k) in indices(2)]
    assert close(levels[1], want)
    assert close(levels[3][0], patch_exact(P3, None, u, v))


def test_derivs_are_blossoms(cubic):
    for u, v in UV:
        p = (Fraction(u), Fraction(v), 1 - Fraction(u) - Fraction(v))
        for d in [(-1, 1, 0), (-1, 0, 1), (0.5, 0.25, -0.75)]:
            dd = tuple(Fraction(x) for x in d)
            got = cubic.derivs(u, v, d, 3)
            assert got.shape == (4, 3)
            for k in range(4):
                scale = factorial(3) // factorial(3 - k)
                want = [scale * x for x in
                        blossom_exact(P3, [dd] * k + [p] * (3 - k))]
                assert close(got[k], want, 64 * EPS)


def test_normal(cubic):
    for u, v in UV[3:]:
        p = (Fraction(u), Fraction(v), 1 - Fraction(u) - Fraction(v))
        du = [3 * float(x) for x in blossom_exact(P3, [(-1, 1, 0), p, p])]
        dv = [3 * float(x) for x in blossom_exact(P3, [(-1, 0, 1), p, p])]
        n = np.cross(du, dv)
        assert close(cubic.normal(u, v), n / np.linalg.norm(n), 16 * EPS)
    assert cubic.normal([0.1, 0.2], 0.3).shape == (2, 3)


def test_subdivide_and_elevate(rational):
    u, v = 0.2, 0.3
    pt = np.array([u, v, 1 - u - v])
    corners = np.eye(3)
    parts = rational.subdivide(u, v)
    assert len(parts) == 3
    for m, part in enumerate(parts):
        # part m has the corners of the triangle with corner m replaced by p
        c = corners.copy()
        c[m] = pt
        for a, b in [(0.2, 0.2), (0.5, 0.1), (0.0, 1.0), (1 / 3, 1 / 3)]:
            q = np.array([a, b, 1 - a - b]) @ c
            assert close(part.eval(a, b),
                         patch_exact(P3, W3, q[0], q[1]), 64 * EPS)
    up = rational.elevate()
    assert up.degree == 4 and up.points.shape == (15, 3)
    for u, v in UV:
        assert close(up.eval(u, v), patch_exact(P3, W3, u, v), 16 * EPS)


def test_boundary(rational):
    t = np.linspace(0.0, 1.0, 5)
    maps = [lambda s: (1 - s, s), lambda s: (0.0, 1 - s), lambda s: (s, 0.0)]
    for e, m in enumerate(maps):
        c = rational.boundary(e)
        assert isinstance(c, curvefig.Bezier) and c.degree == 3
        for s in t:
            assert close(c.eval(s), patch_exact(P3, W3, *m(s)), 16 * EPS)


def test_bad_input(cubic):
    with pytest.raises(ValueError, match="7 points.*6 or 10"):
        curvefig.BezierTriangle(np.zeros((7, 3)))
    with pytest.raises(ValueError, match="3 weights given for 10 points"):
        curvefig.BezierTriangle(np.array(P3, float), weights=[1, 2, 3])
    with pytest.raises(ValueError, match="weight of b_120 is -1"):
        curvefig.BezierTriangle(np.array(P3, float),
                                weights=[1, 1, 1, -1, 1, 1, 1, 1, 1, 1])
    with pytest.raises(ValueError, match=r"P\[3, 1\] is nan"):
        curvefig.BezierTriangle(np.where(np.arange(30).reshape(10, 3) == 10,
                                         np.nan, np.array(P3, float)))
    with pytest.raises(ValueError, match=r"\(0.9, 0.3, -0.2.*outside"):
        cubic.eval(0.9, 0.3)
    with pytest.raises(ValueError, match="outside"):
        cubic.eval([0.1, 0.2, 1.5], 0.0)
    with pytest.raises(ValueError, match="must sum to 0"):
        cubic.derivs(0.1, 0.1, (1, 1, 0))
    with pytest.raises(ValueError, match="direction has 2 coordinates"):
        cubic.derivs(0.1, 0.1, (1, -1))
    with pytest.raises(ValueError, match="order is 17"):
        cubic.derivs(0.1, 0.1, (1, -1, 0), 17)
    with pytest.raises(ValueError, match="edge 3"):
        cubic.boundary(3)
    with pytest.raises(ValueError, match=r"\(-0.5, 0.2, 1.3\) is not a point"):
        cubic.subdivide(-0.5, 0.2)
    with pytest.raises(ValueError, match="R\\^2; normals need R\\^3"):
        curvefig.BezierTriangle(np.zeros((3, 2))).normal(0.2, 0.2)
    with pytest.raises((ValueError, TypeError)):
        cubic.decasteljau(float("nan"), 0.1)


def test_same_bits_as_the_language(rational, tmp_path):
    """bezier_triangle{} of the language and BezierTriangle call the same C
    functions: eval, derivs and the subdivided patch agree to the last bit;
    the language counts edges from 1."""
    code = """
local t = bezier_triangle{ degree = 3, points = { %s }, weights = { %s } }
local function out(p) print(string.format("%%a %%a %%a", p[1], p[2], p[3])) end
out(t:eval(0.25, 0.5))
for _, d in ipairs(t:derivs(0.1, 0.7, {-1, 1, 0}, 2)) do out(d) end
local a, b, c = t:subdivide(0.2, 0.3)
out(b:eval(0.5, 0.1))
out(t:boundary(2):eval(0.3))
""" % (", ".join("{%d, %d, %d}" % tuple(p) for p in P3),
       ", ".join(str(w) for w in W3))
    want = exact_values(run_lua(code, tmp_path)).reshape(6, 3)
    got = np.vstack([rational.eval(0.25, 0.5),
                     rational.derivs(0.1, 0.7, (-1, 1, 0), 2),
                     rational.subdivide(0.2, 0.3)[1].eval(0.5, 0.1),
                     rational.boundary(1).eval(0.3)])
    assert np.array_equal(got, want)
