-- expect: 1 "bspline: knot u_3 is NaN; it must be finite"
-- a NaN knot
local s = bspline{ degree = 2, knots = {0,0,0,0/0,0.6,1,1,1}, points = {{0,0},{1,2},{2,0},{3,2},{4,0}} }
