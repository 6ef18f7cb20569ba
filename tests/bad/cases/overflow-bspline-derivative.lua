-- expect: 1 "derivative: control point 0 of the derivative curve overflows (coordinate 1 is inf)"
-- a B-spline derivative whose points overflow
local s = bspline{ degree = 2, points = { {-1.7e308, 0}, {1.7e308, 1}, {-1.7e308, 0} } }
local d = s:derivative()
