-- expect: 1 "remove_knot: 0.42 is not an interior knot of the domain [0, 1]"
-- removal of a value that is not a knot
local s = bspline{ degree = 2, points = {{0,0},{1,2},{2,0},{3,2},{4,0}} }
local t = s:remove_knot(0.42, 1, 1e-9)
