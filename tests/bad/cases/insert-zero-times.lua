-- expect: 1 "insert_knot: r is 0; it must be in [1, 33]"
-- knot inserted 0 times
local s = bspline{ degree = 2, points = {{0,0},{1,2},{2,0},{3,2},{4,0}} }
local t = s:insert_knot(0.5, 0)
