"""curvefig for Python: the curve library as numpy arrays, and figures that
show themselves in Jupyter.

    import numpy as np, curvefig
    c = curvefig.Bezier([[0, 5], [1, -1], [3, 0], [4, 3], [6, 10]])
    c.eval(np.linspace(0, 1, 5))          # (5, 2) array, one call into C
    f = curvefig.Figure("quartic", width="8cm")
    f.hull(c); f.polygon(c, labels="P_%d"); f.curve(c)
    f                                      # the SVG, in a notebook
    f.save("quartic.pdf")

docs/python.md is the manual.
"""

from ._core import (Bezier, BSpline, BezierSurface, BSplineSurface,
                    BezierTriangle,
                    interpolate, approximate, parameters, nurbs_circle, coons,
                    ferguson, ferguson_chain, coons_cubic, revolve, extrude,
                    ruled, coons_patch, nurbs_sphere, nurbs_cylinder,
                    nurbs_cone, nurbs_torus, interpolate_surface,
                    approximate_surface, version)
from .lua import Lua
from .figure import Figure, ScriptFigure, render_script, have_html

__all__ = ["Bezier", "BSpline", "BezierSurface", "BSplineSurface",
           "BezierTriangle",
           "interpolate", "approximate", "parameters", "nurbs_circle",
           "coons", "ferguson", "ferguson_chain", "coons_cubic", "revolve", "extrude", "ruled", "coons_patch",
           "nurbs_sphere", "nurbs_cylinder", "nurbs_cone", "nurbs_torus",
           "interpolate_surface", "approximate_surface",
           "Figure", "ScriptFigure", "render_script", "Lua",
           "version", "have_html"]
__version__ = version
