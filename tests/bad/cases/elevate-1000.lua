-- expect: 1 "elevate: t is 1000; it must be in [0, 32]"
-- degree elevation of a B-spline to degree 1002
local s = bspline{ degree = 2, points = {{0,0},{1,2},{2,0},{3,2},{4,0}} }
local t = s:elevate(1000)
