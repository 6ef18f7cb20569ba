-- expect: 1 "bspline: knot u_0 (1) has multiplicity 7; degree 1 allows at most 2"
-- all knots equal
local s = bspline{ degree = 1, knots = {1,1,1,1,1,1,1}, points = {{0,0},{1,2},{2,0},{3,2},{4,0}} }
