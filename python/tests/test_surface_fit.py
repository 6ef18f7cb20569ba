"""interpolate_surface and approximate_surface: the surface passes through
the grid at the parameters averaged over the columns and rows (computed
here from curvefig.parameters, NURBS Book §9.2.5); least squares
reproduces a bicubic patch and reports its true residual; bad input."""

import numpy as np
import pytest

import curvefig
from conftest import exact_values, run_lua

EPS = np.finfo(float).eps
RNG = np.random.default_rng(34)
Q = RNG.random((6, 5, 3)) * 4


def averaged_params(Q, param):
    u = np.mean([curvefig.parameters(Q[:, j], param)
                 for j in range(Q.shape[1])], axis=0)
    v = np.mean([curvefig.parameters(Q[i], param)
                 for i in range(Q.shape[0])], axis=0)
    return u, v


@pytest.mark.parametrize("method,degree,param", [
    (None, 3, None), ("global", 2, "uniform"),
    ("not-a-knot", 3, "centripetal"), ("catmull-rom", 3, "chord")])
def test_interpolate_surface(method, degree, param):
    s = curvefig.interpolate_surface(Q, method=method, degree=degree,
                                     param=param)
    assert isinstance(s, curvefig.BSplineSurface)
    u, v = averaged_params(Q, param)
    got = s.eval(u[:, None], v[None, :])
    assert got.shape == Q.shape
    # the solve of a banded system: a few hundred ulps of the data's size
    assert np.max(np.abs(got - Q)) <= 256 * EPS * np.max(np.abs(Q))


def test_approximate_surface():
    # a bicubic Bézier patch sampled at uniform parameters: the least
    # squares fit with 4 x 4 points on [0, 1]^2 is the patch itself
    B = curvefig.BezierSurface(RNG.random((4, 4, 3)))
    t = np.linspace(0.0, 1.0, 9)
    grid = B.eval(t[:, None], t[None, :])
    s, res = curvefig.approximate_surface(grid, (4, 4), param="uniform")
    assert res <= 64 * EPS
    w = np.linspace(0.0, 1.0, 13)
    assert np.max(np.abs(s.eval(w[:, None], w[None, :])
                         - B.eval(w[:, None], w[None, :]))) <= 1e-13
    # fewer points: the reported residual is the largest distance at the
    # data's parameters
    s, res = curvefig.approximate_surface(Q, (4, 3), degree=2,
                                          fix_ends=False)
    assert s.points.shape == (4, 3, 3) and s.degree == (2, 2)
    u, v = averaged_params(Q, None)
    dist = np.linalg.norm(s.eval(u[:, None], v[None, :]) - Q, axis=-1)
    assert res > 0.1 and abs(res - dist.max()) <= 1e-12 * res


def test_surface_fit_bad_input():
    with pytest.raises(ValueError, match=r"shape \(1, 5, 3\).*2 x 2"):
        curvefig.interpolate_surface(Q[:1])
    with pytest.raises(ValueError, match="no explicit parameters, end "
                       "tangents, closed or periodic"):
        curvefig.interpolate_surface(Q, method="clamped")
    with pytest.raises(ValueError, match='unknown interpolation method "n'):
        curvefig.interpolate_surface(Q, method="nope")
    bad = Q.copy()
    bad[2, 3, 1] = np.nan
    with pytest.raises(ValueError, match=r"\[2, 3, 1\] is nan"):
        curvefig.interpolate_surface(bad)
    with pytest.raises(ValueError, match=r"count is \(1, 3\)"):
        curvefig.approximate_surface(Q, (1, 3))
    with pytest.raises(ValueError, match="9 control points needs at least "
                       "9 points, got 6"):
        curvefig.approximate_surface(Q, (9, 3))
    with pytest.raises(TypeError):
        curvefig.approximate_surface(Q, 3)


def test_same_bits_as_the_language(tmp_path):
    """interpolate_surface{} of the language (with and without count) and
    the module's functions call the same C functions: the values agree to
    the last bit."""
    G = np.round(Q * 64) / 64                 # exact in the script's text
    rows = ", ".join("{ %s }" % ", ".join(
        "{%r, %r, %r}" % tuple(map(float, p)) for p in row) for row in G)
    code = """
local Q = { %s }
local s = interpolate_surface{ points = Q, method = "global", degree = 2 }
local a = interpolate_surface{ points = Q, count = {4, 3}, degree = 2 }
for _, S in ipairs{ s, a } do
  local p = S:eval(0.3, 0.8)
  print(string.format("%%a %%a %%a", p[1], p[2], p[3]))
end
""" % rows
    want = exact_values(run_lua(code, tmp_path)).reshape(2, 3)
    s = curvefig.interpolate_surface(G, method="global", degree=2)
    a, _ = curvefig.approximate_surface(G, (4, 3), degree=2)
    assert np.array_equal(np.vstack([s.eval(0.3, 0.8), a.eval(0.3, 0.8)]),
                          want)
