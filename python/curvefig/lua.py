"""Python values written as Lua source of the figure language.

A Figure (figure.py) is a script of the language; its arguments are written
here as Lua literals: numbers with Python's repr (the shortest text that
reads back as the same double, so nothing is rounded), strings quoted,
arrays as nested tables, dicts as tables of keys, and the curves and
surfaces of curvefig as the language's constructors of the same control
points, knots and weights.
"""

import math
import re

import numpy as np

from . import _core

_NAME = re.compile(r"^[A-Za-z_][A-Za-z0-9_]*$")
_KEYWORDS = frozenset(
    "and break do else elseif end false for function goto if in local nil "
    "not or repeat return then true until while".split())


class Lua:
    """A Lua expression written into the script as it is:
    ``fig.label(curvefig.Lua("P[1]"), "P_0")``."""

    def __init__(self, code):
        if not isinstance(code, str):
            raise TypeError("Lua: the code must be a string")
        self.code = code

    def __repr__(self):
        return "Lua(%r)" % self.code


def _string(s):
    out = ['"']
    for ch in s:
        o = ord(ch)
        if ch == '"' or ch == "\\":
            out.append("\\" + ch)
        elif ch == "\n":
            out.append("\\n")
        elif o < 0x20 or o == 0x7F:
            out.append("\\%03d" % o)
        else:
            out.append(ch)
    out.append('"')
    return "".join(out)


def _number(v, where):
    if isinstance(v, (bool, np.bool_)):
        return "true" if v else "false"
    if isinstance(v, (int, np.integer)):
        return str(int(v))
    v = float(v)
    if not math.isfinite(v):
        raise ValueError("%s: the number %r is not finite" % (where, v))
    return repr(v)


def _array(a, where):
    if a.dtype.kind not in "biuf":
        raise TypeError("%s: an array of dtype %s cannot be written as "
                        "numbers" % (where, a.dtype))
    if a.ndim == 0:
        return _number(a[()], where)
    return "{" + ", ".join(_array(x, where) for x in a) + "}"


def _curve(c, where):
    if isinstance(c, _core.Bezier):
        s = "bezier{ points = %s" % _array(c.points, where)
        if c.is_rational:
            s += ", weights = %s" % _array(c.weights, where)
        return s + " }"
    if isinstance(c, _core.BSpline):
        s = "bspline{ degree = %d, knots = %s, points = %s" % (
            c.degree, _array(c.knots, where), _array(c.points, where))
        if c.is_rational:
            s += ", weights = %s" % _array(c.weights, where)
        return s + " }"
    if isinstance(c, _core.BezierSurface):
        s = "bezier_surface{ points = %s" % _array(c.points, where)
        if c.is_rational:
            s += ", weights = %s" % _array(c.weights, where)
        return s + " }"
    if isinstance(c, _core.BSplineSurface):
        U, V = c.knots
        s = "bspline_surface{ degree = {%d, %d}, knots = {%s, %s}, " \
            "points = %s" % (c.degree + (_array(U, where), _array(V, where),
                                         _array(c.points, where)))
        if c.is_rational:
            s += ", weights = %s" % _array(c.weights, where)
        return s + " }"
    return None


CURVES = (_core.Bezier, _core.BSpline, _core.BezierSurface,
          _core.BSplineSurface)


def literal(v, where="figure", ref=None):
    """v as Lua source.  ref(v) may name a value already in the script
    (a curve written once, a result of an earlier call); else None."""
    if ref is not None:
        name = ref(v)
        if name is not None:
            return name
    if v is None:
        return "nil"
    if isinstance(v, Lua):
        return v.code
    if isinstance(v, (bool, int, float, np.bool_, np.integer, np.floating)):
        return _number(v, where)
    if isinstance(v, str):
        return _string(v)
    if isinstance(v, np.ndarray):
        return _array(v, where)
    c = _curve(v, where)
    if c is not None:
        return c
    if isinstance(v, dict):
        items = []
        for k, x in v.items():
            if not isinstance(k, str):
                raise TypeError("%s: option names must be strings, got %r"
                                % (where, k))
            key = k if _NAME.match(k) and k not in _KEYWORDS \
                else "[%s]" % _string(k)
            items.append("%s = %s" % (key, literal(x, where, ref)))
        return "{ " + ", ".join(items) + " }"
    if isinstance(v, (list, tuple)):
        return "{" + ", ".join(literal(x, where, ref) for x in v) + "}"
    raise TypeError("%s: a %s cannot be passed to the figure language"
                    % (where, type(v).__name__))
