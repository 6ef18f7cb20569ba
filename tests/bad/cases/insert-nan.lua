-- expect: 1 "insert_knot: u is "
-- knot insertion at NaN
local s = bspline{ degree = 2, points = {{0,0},{1,2},{2,0},{3,2},{4,0}} }
local t = s:insert_knot(0/0)
