-- expect: 1 "tangent: t = 7 is outside the domain [0, 2]"
-- the same for a B-spline, whose domain is its own
local f = figure{ name = 'z' }
local s = bspline{ degree = 1, knots = { 0, 0, 1, 2, 2 }, points = { {0, 0}, {1, 1}, {2, 0} } }
f:tangent(s, 7)
