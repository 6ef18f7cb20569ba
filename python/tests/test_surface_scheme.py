"""The surfaces' schemes and patches: decasteljau against exact rational
arithmetic, deboor against the curves' de Boor on each column and scipy's
basis, to_beziers and knot_lines against the knots; bad input."""

from fractions import Fraction

import numpy as np
import pytest

import curvefig

scipy_interpolate = pytest.importorskip("scipy.interpolate")

EPS = np.finfo(float).eps
RNG = np.random.default_rng(34)
NET = np.round(RNG.random((4, 3, 3)) * 16) / 4       # exact quarters
U = [0, 0, 0, 0.3, 0.3, 0.6, 1, 1, 1]                # p = 2, a double knot
V = [0, 0, 0, 0, 0.5, 1, 1, 1, 1]                    # q = 3
GRID = np.round(RNG.random((6, 5, 3)) * 8) / 2


def casteljau_exact(pts, t):
    """All levels of de Casteljau in exact rationals."""
    t = Fraction(t)
    levels = [[[Fraction(x) for x in p] for p in pts]]
    while len(levels[-1]) > 1:
        lev = levels[-1]
        levels.append([[(1 - t) * a + t * b for a, b in zip(p, q)]
                       for p, q in zip(lev, lev[1:])])
    return levels


def same(a, b, tol=8 * EPS):
    a, b = np.asarray(a, float), np.asarray(b, float)
    return a.shape == b.shape and np.max(np.abs(a - b)) <= tol * max(
        1.0, np.max(np.abs(b)))


def test_bezier_surface_decasteljau():
    s = curvefig.BezierSurface(NET)
    for u, v in [(0.0, 0.0), (0.25, 0.75), (1.0, 0.5), (0.3, 0.1)]:
        cols, vnet = s.decasteljau(u, v)
        assert len(cols) == 3 and [len(c) for c in cols] == [4, 4, 4]
        tops = []
        for j, col in enumerate(cols):
            want = casteljau_exact(NET[:, j], u)
            assert all(same(a, [[float(x) for x in p] for p in w])
                       for a, w in zip(col, want))
            tops.append(want[-1][0])
        want = casteljau_exact([[float(x) for x in p] for p in tops], v)
        assert [lev.shape for lev in vnet] == [(3, 3), (2, 3), (1, 3)]
        assert same(vnet[-1][0], [float(x) for x in want[-1][0]])
        assert same(vnet[-1][0], s.eval(u, v))


def basis(knots, p, t):
    n = len(knots) - p - 1
    return scipy_interpolate.BSpline(np.array(knots, float), np.eye(n),
                                     p)(t)


def test_bspline_surface_deboor():
    s = curvefig.BSplineSurface((2, 3), (U, V), GRID)
    for u, v in [(0.0, 0.0), (0.3, 0.2), (0.45, 0.5), (1.0, 1.0),
                 (0.7, 0.9)]:
        (cols, vnet), (su, sv) = s.deboor(u, v)
        assert len(cols) == 4 and all(len(c) == 3 for c in cols)
        for c, j in enumerate(range(sv - 3, sv + 1)):
            col = curvefig.BSpline(2, U, GRID[:, j])
            levels, span, _ = col.deboor(u)
            assert span == su
            assert len(levels) == 3
            assert all(same(a, b) for a, b in zip(cols[c], levels))
        # S(u, v) = sum N_i(u) N_j(v) P_ij, with scipy's basis
        want = np.einsum("i,j,ijk->k", basis(U, 2, u), basis(V, 3, v), GRID)
        assert same(vnet[-1][0], want, 16 * EPS)
        assert U[su] <= u <= U[su + 1] and V[sv] <= v <= V[sv + 1]


def test_to_beziers_and_knot_lines():
    s = curvefig.BSplineSurface((2, 3), (U, V), GRID,
                                weights=1 + RNG.random((6, 5)))
    ku, kv = s.knot_lines("u"), s.knot_lines("v")
    assert np.array_equal(ku, [0, 0.3, 0.6, 1])
    assert np.array_equal(kv, [0, 0.5, 1])
    grid = s.to_beziers()
    assert len(grid) == 3 and all(len(row) == 2 for row in grid)
    ab = np.linspace(0.0, 1.0, 5)
    for i, row in enumerate(grid):
        for j, patch in enumerate(row):
            assert isinstance(patch, curvefig.BezierSurface)
            assert patch.degree == (2, 3) and patch.is_rational
            u = ku[i] + ab[:, None] * (ku[i + 1] - ku[i])
            v = kv[j] + ab[None, :] * (kv[j + 1] - kv[j])
            assert same(patch.eval(ab[:, None], ab[None, :]), s.eval(u, v),
                        64 * EPS)


def test_scheme_bad_input():
    bz = curvefig.BezierSurface(NET)
    bs = curvefig.BSplineSurface((2, 3), (U, V), GRID)
    with pytest.raises(ValueError, match=r"\(1.5, 0.5\) is outside the "
                       r"domain \[0, 1\] x \[0, 1\]"):
        bz.decasteljau(1.5, 0.5)
    with pytest.raises(ValueError, match=r"\(0.5, -0.25\) is outside"):
        bs.deboor(0.5, -0.25)
    with pytest.raises((ValueError, TypeError), match="v"):
        bs.deboor(0.5, float("nan"))
    with pytest.raises(ValueError, match="knot_lines"):
        bs.knot_lines("w")
    assert not hasattr(bz, "deboor") and not hasattr(bs, "decasteljau")
