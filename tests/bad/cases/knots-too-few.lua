-- expect: 1 "bspline: 7 knots given, degree 2 with 5 points needs 8"
-- one knot missing
local s = bspline{ degree = 2, knots = {0,0,0,0.5,1,1,1}, points = {{0,0},{1,2},{2,0},{3,2},{4,0}} }
