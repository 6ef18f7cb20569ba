-- expect: 1 "bspline: knot u_4 (0.30) is smaller than knot u_3 (0.50)"
-- a knot smaller than its predecessor
local s = bspline{ degree = 2, knots = {0,0,0,0.5,0.3,1,1,1}, points = {{0,0},{1,2},{2,0},{3,2},{4,0}} }
