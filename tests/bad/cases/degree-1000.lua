-- expect: 1 "bspline: degree is 1000; it must be in [0, 32]"
-- B-spline of degree 1000
local s = bspline{ degree = 1000, points = {{0,0},{1,2},{2,0},{3,2},{4,0}} }
