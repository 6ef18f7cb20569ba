-- expect: 1 "remove_knot: tolerance -1 must be finite and >= 0"
-- removal with a negative tolerance
local s = bspline{ degree = 2, points = {{0,0},{1,2},{2,0},{3,2},{4,0}} }
local t = s:remove_knot(s:knots()[4], 1, -1)
