-- expect: 1 "surface: degenerate patch: its 4 control points lie on one line"
-- a bilinear patch whose corners lie on one line
local f = figure{ name = 'z', view = { 30, 20 } }
f:surface(bezier_surface{ points = { { {0, 0, 0}, {1, 1, 1} },
                                     { {2, 2, 2}, {3, 3, 3} } } })
