-- expect: 1 "derivative: control point 0 of the derivative curve overflows (coordinate 1 is inf)"
-- a B-spline derivative over knot spans of 1e-320
local t = 1e-320
local s = bspline{ degree = 2, knots = {0, 0, 0, t, 2*t, 2*t, 2*t}, points = { {0, 0}, {1, 1}, {2, 0}, {3, 1} } }
local d = s:derivative()
