-- expect: 1 "surface: argument 1 must be a surface (bezier_surface{...}, bspline_surface{...}, nurbs_torus{...}, ...), got table"
-- a list of points where a surface belongs
local f = figure{ name = 'z', view = { 30, 20 } }
f:surface({ {0, 0, 0}, {1, 1, 1} })
