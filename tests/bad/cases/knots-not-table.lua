-- expect: 1 "bspline: knot must be a table, got number"
-- knots given as a number
local s = bspline{ degree = 2, knots = 5, points = {{0,0},{1,2},{2,0},{3,2},{4,0}} }
