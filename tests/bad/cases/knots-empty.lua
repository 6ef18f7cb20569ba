-- expect: 1 "bspline: 0 knots given, degree 2 with 5 points needs 8"
-- an empty knot list
local s = bspline{ degree = 2, knots = {}, points = {{0,0},{1,2},{2,0},{3,2},{4,0}} }
