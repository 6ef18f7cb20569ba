-- expect: 1 "bspline: knot 4 is "
-- a NaN knot
local s = bspline{ degree = 2, knots = {0,0,0,0/0,0.6,1,1,1}, points = {{0,0},{1,2},{2,0},{3,2},{4,0}} }
