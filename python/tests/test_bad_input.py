"""Bad input raises a clear exception naming what is wrong, and never
crashes the interpreter; arrays that are merely strided or in Fortran
order are read correctly."""

import sys

import numpy as np
import pytest

import curvefig
from conftest import CUBIC_P, KNOTS, QUARTIC


@pytest.mark.parametrize("P, exc, words", [
    ([[0, 1], [1]], ValueError, "P must be an array of numbers"),
    ([[0, 1], [1, "x"]], ValueError, "P must be an array of numbers"),
    (np.array([["a", "b"]]), TypeError, "dtype <U1"),
    (np.array([[1 + 2j, 0]]), TypeError, "dtype complex128"),
    (np.array([[None, 1]], dtype=object), TypeError, "dtype object"),
    ([[0, np.nan], [1, 2]], ValueError, "P[0, 1] is nan"),
    ([[0, 1], [np.inf, 2]], ValueError, "P[1, 0] is inf"),
    ([1, 2, 3], ValueError, "must have 2 dimensions"),
    (np.zeros((0, 2)), ValueError, "at least 1 point"),
    (None, ValueError, "P is missing"),
    ("text", ValueError, "P must be an array of numbers"),
])
def test_bezier_points(P, exc, words):
    with pytest.raises(exc) as e:
        curvefig.Bezier(P)
    assert words in str(e.value) and str(e.value).startswith("Bezier:")


def test_weights():
    with pytest.raises(ValueError, match="3 weights for 5 points"):
        curvefig.Bezier(QUARTIC, weights=[1, 2, 3])
    with pytest.raises(ValueError, match="weight"):
        curvefig.Bezier(QUARTIC, weights=[1, -1, 1, 1, 1])
    with pytest.raises(ValueError, match=r"weights\[2\] is nan"):
        curvefig.Bezier(QUARTIC, weights=[1, 1, np.nan, 1, 1])


def test_knots():
    bad = list(KNOTS)
    bad[5] = 0.1
    with pytest.raises(ValueError, match=r"^BSpline: knot"):
        curvefig.BSpline(3, bad, CUBIC_P)
    with pytest.raises(ValueError, match="BSpline"):
        curvefig.BSpline(3, KNOTS[:-1], CUBIC_P)
    with pytest.raises(ValueError, match="BSpline"):
        curvefig.BSpline(-1, KNOTS, CUBIC_P)
    with pytest.raises(ValueError, match=r"knots\[3\] is nan"):
        curvefig.BSpline(3, KNOTS[:3] + [np.nan] + KNOTS[4:], CUBIC_P)
    with pytest.raises(ValueError, match="closed"):
        curvefig.BSpline(3, "open", CUBIC_P)


def test_parameters(quartic, spline):
    with pytest.raises(ValueError, match=r"parameter 2 \(1.5\) is outside "
                       r"the domain \[0, 1\]"):
        quartic.eval([0.0, 0.5, 1.5])
    with pytest.raises(ValueError, match="parameter 1 is nan"):
        spline.eval(np.array([0.5, np.nan]))
    with pytest.raises(ValueError, match="parameter 0 is inf"):
        quartic.derivs(np.inf)
    with pytest.raises(TypeError, match="dtype"):
        quartic.eval(np.array(["0.5"]))
    with pytest.raises(ValueError, match="split"):
        quartic.split(1.0)
    with pytest.raises(ValueError, match="decasteljau"):
        quartic.decasteljau(float("nan"))
    with pytest.raises(ValueError, match="order"):
        quartic.derivs(0.5, -1)
    with pytest.raises(TypeError):
        quartic.split("half")


def test_strided_and_fortran_arrays(quartic, spline):
    """Views are copied once into C order, never read wrongly."""
    big = np.linspace(0, 1, 2001)
    view = big[::4]
    assert not view.flags.c_contiguous
    assert np.array_equal(quartic.eval(view), quartic.eval(view.copy()))
    P = np.asfortranarray(np.array(CUBIC_P, float))
    assert not P.flags.c_contiguous
    s = curvefig.BSpline(3, KNOTS, P)
    assert np.array_equal(s.eval(view), spline.eval(view))
    Q = np.zeros((5, 4))
    Q[:, ::2] = QUARTIC
    assert np.array_equal(curvefig.Bezier(Q[:, ::2]).points, quartic.points)
    # integers and booleans are numbers
    assert np.array_equal(curvefig.Bezier(np.array(QUARTIC)).eval(0.5),
                          quartic.eval(0.5))


def test_other_functions(quartic, spline):
    with pytest.raises(ValueError, match="method"):
        curvefig.interpolate(CUBIC_P, method="cubic-ish")
    with pytest.raises(ValueError, match="param"):
        curvefig.interpolate(CUBIC_P, param="arc")
    with pytest.raises(ValueError, match="tolerance"):
        quartic.to_cubics(0.0)
    with pytest.raises(ValueError, match="method"):
        quartic.offset(0.1, method="exact")
    with pytest.raises(ValueError, match="coordinates"):
        quartic.closest([1, 2, 3])
    with pytest.raises(ValueError, match="A must be 2 x 2"):
        quartic.transform(np.eye(3))
    with pytest.raises(ValueError, match="direction"):
        curvefig.BezierSurface(np.zeros((2, 2, 3))).iso("w", 0.5)
    with pytest.raises(ValueError, match="grid"):
        curvefig.BezierSurface(np.zeros((2, 0, 3)))
    with pytest.raises(ValueError, match="support"):
        spline.support(99)


def test_immutable(quartic):
    with pytest.raises(AttributeError):
        quartic.degree = 3
    pts = quartic.points
    pts[0, 0] = 99.0
    assert quartic.points[0, 0] == 0.0


def test_figure_errors(quartic):
    f = curvefig.Figure("bad")
    f.curv(quartic)
    with pytest.raises(ValueError) as e:
        f.render("svg")
    msg = str(e.value)
    # the language's message, and the Python line that made the call
    assert "did you mean 'curve'" in msg and "test_bad_input.py" in msg
    with pytest.raises(ValueError, match="not finite"):
        curvefig.Figure("nan").points([[0, float("nan")]])
    with pytest.raises(ValueError, match="unknown format"):
        curvefig.Figure("x").save("x.docx")
    with pytest.raises(ValueError, match="script:1:"):
        curvefig.render_script("this is not lua\n")
    with pytest.raises(TypeError, match="cannot be passed"):
        curvefig.Figure("x").curve(object())


def test_render_error_names_the_python_line(quartic):
    # a page error names the element by its line: the Python file and line
    # that added it, not the line of the generated script
    f = curvefig.Figure("far")
    f.curve(quartic)
    line = sys._getframe().f_lineno + 1
    f.label([0.5, 0.5], "P", offset=1e300)
    with pytest.raises(ValueError) as e:
        f.render("svg")
    msg = str(e.value)
    assert 'label 2 "P" (%s, line %d) lies' % (__file__, line) in msg, msg
