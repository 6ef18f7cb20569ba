-- expect: 1 "bspline: knot u_2 (0.5) has multiplicity 3; degree 1 allows at most 2"
-- interior knot of multiplicity p + 2
local s = bspline{ degree = 1, knots = {0,0,0.5,0.5,0.5,1,1}, points = {{0,0},{1,2},{2,0},{3,2},{4,0}} }
