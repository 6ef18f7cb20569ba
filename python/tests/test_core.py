"""The curves as arrays: values against exact rational arithmetic, against
the C library through the language (bit for bit), against scipy on the same
curves, and the identities of the constructions."""

from fractions import Fraction

import numpy as np
import pytest

import curvefig
from conftest import CUBIC_P, KNOTS, QUARTIC, exact_values, run_lua

scipy_interpolate = pytest.importorskip("scipy.interpolate")

T = np.linspace(0.0, 1.0, 101)
EPS = np.finfo(float).eps


def rel_err(a, b):
    return np.max(np.abs(np.asarray(a) - np.asarray(b))) / max(
        1.0, np.max(np.abs(b)))


def decasteljau_exact(P, t):
    """de Casteljau in exact rationals."""
    t = Fraction(t)
    pts = [[Fraction(x) for x in p] for p in P]
    while len(pts) > 1:
        pts = [[(1 - t) * a + t * b for a, b in zip(p, q)]
               for p, q in zip(pts, pts[1:])]
    return [float(x) for x in pts[0]]


def test_bezier_eval_exact(quartic):
    got = quartic.eval(T)
    want = np.array([decasteljau_exact(QUARTIC, t) for t in T])
    assert got.shape == (101, 2) and got.dtype == np.float64
    # a few ulps of the curve's size (the core's fast evaluator agrees with
    # de Casteljau to a few ulps: bezier.h)
    assert rel_err(got, want) < 8 * np.finfo(float).eps


def test_eval_into_out(quartic, spline):
    out = np.empty((101, 2))
    assert quartic.eval(T, out=out) is out
    assert np.array_equal(out, quartic.eval(T))
    assert spline.eval(T, out=out) is out
    assert np.array_equal(out, spline.eval(T))
    for bad in (np.empty((101, 3)), np.empty((2, 101)).T,
                np.empty((101, 2), np.float32), [[0.0, 0.0]] * 101):
        with pytest.raises(ValueError, match="out must be"):
            quartic.eval(T, out=bad)
    ro = np.empty((101, 2))
    ro.flags.writeable = False
    with pytest.raises(ValueError, match="writeable"):
        spline.eval(T, out=ro)


def test_eval_shapes(quartic, spline):
    assert quartic.eval(0.5).shape == (2,)
    assert quartic.eval(np.zeros((3, 4))).shape == (3, 4, 2)
    assert spline.eval([[0.1, 0.2]]).shape == (1, 2, 2)
    assert quartic.derivs(0.5, 2).shape == (3, 2)
    assert quartic.derivs(T, 3).shape == (101, 4, 2)
    assert quartic.eval(np.array([], dtype=float)).shape == (0, 2)


def test_same_bits_as_the_language(quartic, spline, tmp_path):
    """The module and the language call the same C functions (the batch
    evaluators for a list of parameters): the values agree to the last bit
    (printed with %a)."""
    ts = [0.0, 0.1, 0.25, 1 / 3, 0.5, 0.9, 1.0]
    code = """
local c = bezier{ %s }
local s = bspline{ degree = 3, knots = { %s }, points = { %s } }
local ts = { %s }
local P, Q = c:eval(ts), s:eval(ts)
for i = 1, #ts do
  print(string.format("%%a %%a %%a %%a", P[i][1], P[i][2], Q[i][1], Q[i][2]))
end
""" % (", ".join("{%d, %d}" % tuple(p) for p in QUARTIC),
       ", ".join(repr(float(k)) for k in KNOTS),
       ", ".join("{%d, %d}" % tuple(p) for p in CUBIC_P),
       ", ".join(repr(t) for t in ts))
    want = exact_values(run_lua(code, tmp_path)).reshape(len(ts), 4)
    got = np.hstack([quartic.eval(ts), spline.eval(ts)])
    assert np.array_equal(got, want)


def test_bspline_against_scipy(spline):
    ref = scipy_interpolate.BSpline(np.array(KNOTS, float),
                                    np.array(CUBIC_P, float), 3)
    assert rel_err(spline.eval(T), ref(T)) < 1e-14
    d = spline.derivs(T, 2)
    assert rel_err(d[:, 1], ref.derivative(1)(T)) < 1e-13
    assert rel_err(d[:, 2], ref.derivative(2)(T)) < 1e-12


def test_bezier_against_scipy(quartic):
    ref = scipy_interpolate.BPoly(np.array(QUARTIC, float)[:, None, :],
                                  [0.0, 1.0])
    assert rel_err(quartic.eval(T), ref(T)) < 1e-14
    assert rel_err(quartic.derivs(T, 1)[:, 1], ref.derivative()(T)) < 1e-13


def test_nurbs_circle_is_round():
    c = curvefig.nurbs_circle([1.0, 2.0], 3.0)
    a, b = c.domain
    p = c.eval(np.linspace(a, b, 1001))
    r = np.hypot(p[:, 0] - 1.0, p[:, 1] - 2.0)
    assert np.max(np.abs(r - 3.0)) < 1e-14 * 3


def test_constructions_keep_the_curve(quartic, spline):
    e = quartic.elevate(3)
    assert e.degree == 7 and rel_err(e.eval(T), quartic.eval(T)) < 1e-14
    left, right = quartic.split(0.3)
    assert rel_err(left.eval(T), quartic.eval(0.3 * T)) < 1e-14
    assert rel_err(right.eval(T), quartic.eval(0.3 + 0.7 * T)) < 1e-14
    k = spline.insert_knot(0.35, 2)
    assert k.count == spline.count + 2
    assert rel_err(k.eval(T), spline.eval(T)) < 1e-14
    r = spline.refine([0.1, 0.6, 0.6])
    assert rel_err(r.eval(T), spline.eval(T)) < 1e-14
    pieces = spline.to_beziers()
    assert all(isinstance(b, curvefig.Bezier) for b in pieces)
    assert rel_err(spline.elevate(1).eval(T), spline.eval(T)) < 1e-13
    # the receiver never changes
    assert np.array_equal(spline.points, np.array(CUBIC_P, float))
    assert quartic.degree == 4


def test_decasteljau_and_deboor(quartic, spline):
    levels = quartic.decasteljau(0.75)
    assert [lv.shape for lv in levels] == [(5, 2), (4, 2), (3, 2), (2, 2),
                                           (1, 2)]
    assert np.array_equal(levels[0], np.array(QUARTIC, float))
    assert rel_err(levels[-1][0], decasteljau_exact(QUARTIC, 0.75)) < 1e-15
    net, span, mult = spline.deboor(0.3)
    assert span == 4 and mult == 0 and len(net) == 4
    assert rel_err(net[-1][0], spline.eval(0.3)) < 1e-15
    first, N = spline.basis(0.3)
    assert first == 1 and abs(N.sum() - 1.0) < 1e-15


def test_derivative_matches_derivs(quartic, spline):
    assert rel_err(quartic.derivative().eval(T), quartic.derivs(T)[:, 1]) \
        < 1e-13
    assert rel_err(spline.derivative(2).eval(T), spline.derivs(T, 2)[:, 2]) \
        < 1e-12


def test_rational(quartic):
    w = [1, 2, 0.5, 3, 1]
    r = curvefig.Bezier(QUARTIC, weights=w)
    assert r.is_rational and np.array_equal(r.weights, w)
    # the rational curve from its homogeneous form, exactly
    H = np.array([[p[0] * wi, p[1] * wi, wi] for p, wi in zip(QUARTIC, w)])
    for t in (0.0, 0.2, 0.5, 0.8, 1.0):
        h = decasteljau_exact(H.tolist(), t)
        want = [h[0] / h[2], h[1] / h[2]]
        assert rel_err(r.eval(t), want) < 1e-14
    assert rel_err(curvefig.Bezier(QUARTIC, weights=[1] * 5).eval(T),
                   quartic.eval(T)) < 1e-15


def test_any_dimension():
    P = np.arange(20, dtype=float).reshape(4, 5) ** 1.5
    c = curvefig.Bezier(P)
    assert c.dim == 5 and c.eval(T).shape == (101, 5)
    one = curvefig.Bezier([[0], [3], [1]])
    assert one.eval(0.5).tolist() == [1.75]


def test_interpolation_against_scipy():
    pts = np.array([[0, 0], [1, 2], [2, 1], [4, 3], [5, 0]], float)
    s = curvefig.interpolate(pts, method="natural", param="uniform")
    u = curvefig.parameters(pts, param="uniform")
    assert np.allclose(u, np.linspace(0, 1, 5), rtol=0, atol=1e-15)
    assert rel_err(s.eval(u), pts) < 1e-14
    ref = scipy_interpolate.CubicSpline(u, pts, bc_type="natural")
    assert rel_err(s.eval(T), ref(T)) < 1e-13
    ca = curvefig.approximate(pts, 4)
    assert isinstance(ca[0], curvefig.BSpline) and ca[1] >= 0


def test_offset(quartic):
    curves, report = quartic.offset(0.5, tolerance=1e-4)
    assert report["converged"] and report["max_error"] <= 1e-4
    assert all(c.degree == 3 for c in curves)
    # each piece's ends lie at distance 0.5 from the curve
    for c in curves:
        for p in (c.eval(0.0), c.eval(1.0)):
            assert abs(quartic.closest(p)[1] - 0.5) < 1e-4
    p = quartic.offset_point(T, 0.5)
    assert p.shape == (101, 2)
    assert rel_err(p, quartic.eval(T) + 0.5 * quartic.normal(T)) < 1e-14
    cubics, err = quartic.to_cubics(1e-4)
    assert err <= 1e-4 and all(c.degree == 3 for c in cubics)


def test_surfaces():
    rng = np.random.default_rng(1)
    P = rng.random((3, 4, 3))
    s = curvefig.BezierSurface(P)
    u, v = 0.3, 0.6
    # the tensor product: a Bézier curve of the rows' points at v
    rows = [curvefig.Bezier(P[i]).eval(v) for i in range(3)]
    want = curvefig.Bezier(np.array(rows)).eval(u)
    assert rel_err(s.eval(u, v), want) < 1e-15
    assert s.eval(T, 0.5).shape == (101, 3)
    assert s.eval(T[:, None], T[None, :]).shape == (101, 101, 3)
    iso = s.iso("u", u)
    assert rel_err(iso.eval(v), want) < 1e-15
    b = curvefig.BSplineSurface((2, 3), None, rng.random((4, 5, 3)))
    k = b.insert_knot("v", 0.4, 1)
    assert rel_err(k.eval(T, 0.7), b.eval(T, 0.7)) < 1e-14
    n = b.normal(0.5, 0.5)
    assert abs(np.linalg.norm(n) - 1) < 1e-14


def test_pickle(quartic, spline):
    import pickle
    for c in (quartic, spline):
        d = pickle.loads(pickle.dumps(c))
        assert np.array_equal(d.eval(T), c.eval(T))


def test_threads_share_a_curve(spline):
    """eval releases the GIL; threads evaluating one curve agree."""
    from concurrent.futures import ThreadPoolExecutor
    u = np.linspace(0, 1, 200_000)
    want = spline.eval(u)
    with ThreadPoolExecutor(4) as ex:
        for got in ex.map(lambda _: spline.eval(u), range(8)):
            assert np.array_equal(got, want)


def test_hermite_and_coons_segments():
    """Ferguson's cubic has the control points P0, P0 + T0/3, P1 - T1/3,
    P1; the Coons segment B0 = (P0 + 4 P1 + P2)/6, ...: exact in binary
    for these numbers."""
    P0, P1, T0, T1 = [0, 0], [3, 0], [3, 6], [6, -3]
    f = curvefig.ferguson(P0, P1, T0, T1)
    assert f.points.tolist() == [[0, 0], [1, 2], [1, 1], [3, 0]]
    chain = curvefig.ferguson_chain([[0, 0], [3, 0], [6, 3]],
                                    [[3, 6], [6, -3], [3, 3]])
    assert chain[0].points.tolist() == f.points.tolist()
    assert np.array_equal(chain[1].eval(0.0), [3, 0])
    P = [[0, 0], [6, 6], [12, 0], [18, 6]]
    c = curvefig.coons_cubic(P)
    assert c.points.tolist() == [[6, 4], [8, 4], [10, 2], [12, 2]]


def test_surfaces_made_from_curves():
    u = np.linspace(0, 1, 41)
    S = curvefig.nurbs_sphere([1, 2, 3], 2.0)
    P = S.eval(u[:, None], u[None, :])
    r = np.linalg.norm(P - [1, 2, 3], axis=-1)
    assert np.max(np.abs(r - 2.0)) < 1e-14 * 2
    c = curvefig.Bezier([[1, 0, 0], [2, 0, 1], [1, 0, 2]])
    R = curvefig.revolve(c)          # about the z axis
    Q = R.eval(u[:, None], u[None, :])
    C = c.eval(u)
    # each point keeps its height and its distance from the axis
    assert np.max(np.abs(Q[..., 2] - C[None, :, 2])) < 1e-14
    assert np.max(np.abs(np.hypot(Q[..., 0], Q[..., 1]) - C[None, :, 0])) \
        < 1e-14
    E = curvefig.extrude(c, [0, 3, 0])
    assert rel_err(E.eval(u, 1.0), C + [0, 3, 0]) < 1e-15
    line = curvefig.Bezier([[0, 0, 0], [1, 0, 0]])
    top = curvefig.Bezier([[0, 1, 0], [1, 1, 0]])
    left = curvefig.Bezier([[0, 0, 0], [0, 1, 0]])
    right = curvefig.Bezier([[1, 0, 0], [1, 1, 0]])
    patch = curvefig.coons_patch(line, top, left, right)
    assert rel_err(patch.eval(0.25, 0.75), [0.25, 0.75, 0]) < 1e-15
    ruled = curvefig.ruled(line, top)
    assert rel_err(ruled.eval(0.5, 0.5), [0.5, 0.5, 0]) < 1e-15
    with pytest.raises(TypeError, match="Bezier or a BSpline"):
        curvefig.revolve([[0, 0, 0]])


def test_degree_reduction(quartic, spline):
    """Reducing an elevated curve gives the curve back; the report's
    certified bound is never below the measured error."""
    back, rep = quartic.elevate(2).reduce(by=2)
    assert back.degree == 4 and rel_err(back.eval(T), quartic.eval(T)) < 1e-12
    r, rep = quartic.reduce()
    got = np.max(np.linalg.norm(r.eval(T) - quartic.eval(T), axis=1))
    assert r.degree == 3 and got <= rep["max_error"] * (1 + 1e-9)
    assert rep["max_error"] <= rep["bound"] <= rep["polygon_bound"]
    s, rep = spline.elevate(1).reduce(tolerance=1e-9)
    assert s.degree == 3 and rel_err(s.eval(T), spline.eval(T)) < 1e-12
    with pytest.raises(ValueError, match="method"):
        quartic.reduce(method="best")


def test_offset_trim(quartic):
    """d = 1 on the concave side of the quartic's tight turn: the raw offset
    has a swallowtail (two cusps, one self-intersection); the trimmed
    chains keep only the points at distance d from the curve."""
    d, tol = 1.0, 1e-4
    raw, report, chains = quartic.offset(d, tolerance=tol, trim=True)
    assert len(quartic.offset(d, tolerance=tol)) == 2
    assert report["self_intersections"] >= 1 and report["cusps"] == 2
    assert report["trimmed_chains"] == len(chains) >= 2
    assert report["trimmed_segments"] == sum(len(c) for c in chains)
    s = np.linspace(0.0, 1.0, 17)

    def dist(c):
        return np.array([quartic.closest(p)[1] for p in c.eval(s)])
    # the swallowtail of the raw offset comes closer than d to the curve
    assert min(dist(c).min() for c in raw) < d - 0.05
    for chain in chains:
        for a, b in zip(chain, chain[1:]):
            assert np.allclose(a.eval(1.0), b.eval(0.0), rtol=0, atol=1e-12)
        for c in chain:
            # the fit's tolerance, plus the distance a trimmed end moves
            # along the curve (the intersection is found to 1e-9)
            assert np.all(np.abs(dist(c) - d) <= 2 * tol)


def test_bspline_transform_and_active_points(spline):
    A = np.array([[0.6, -0.8], [0.8, 0.6]]) * 2.0
    b = np.array([1.5, -2.0])
    moved = spline.transform(A, b)
    assert np.array_equal(moved.knots, spline.knots)
    assert rel_err(moved.points, spline.points @ A.T + b) < 4 * EPS
    assert rel_err(moved.eval(T), spline.eval(T) @ A.T + b) < 16 * EPS
    # a NURBS keeps its weights
    w = np.linspace(1.0, 2.0, len(CUBIC_P))
    nurbs = curvefig.BSpline(3, KNOTS, np.array(CUBIC_P, float), weights=w)
    nm = nurbs.transform(A)
    assert np.array_equal(nm.weights, w)
    assert rel_err(nm.eval(T), nurbs.eval(T) @ A.T) < 16 * EPS
    # the span [u_k, u_k+1) containing u, from the knots; the last span is
    # closed at the end of the domain; P_(k-p) .. P_k act on it, and the
    # basis functions of the others vanish there
    U, p = np.array(KNOTS), 3
    for u in np.linspace(0.0, 1.0, 23):
        k = min(np.searchsorted(U, u, side="right") - 1, len(U) - p - 2)
        first, (lo, hi) = spline.active_points(u)
        assert (first, lo, hi) == (k - p, U[k], U[k + 1])
    with pytest.raises(ValueError, match="A must be 2 x 2"):
        spline.transform(np.eye(3))
    with pytest.raises(ValueError, match="b has 3 coordinates"):
        spline.transform(np.eye(2), [1, 2, 3])
    with pytest.raises(ValueError, match=r"\(1.5\) is outside the domain"):
        spline.active_points(1.5)
