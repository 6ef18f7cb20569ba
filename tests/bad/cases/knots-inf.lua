-- expect: 1 "bspline: knot u_4 is inf; it must be finite"
-- an infinite knot
local s = bspline{ degree = 2, knots = {0,0,0,0.5,1/0,1/0,1/0,1/0}, points = {{0,0},{1,2},{2,0},{3,2},{4,0}} }
