-- expect: 1 "insert_knot: parameter 1.5 is outside the domain [0, 1]"
-- knot insertion outside the domain
local s = bspline{ degree = 2, points = {{0,0},{1,2},{2,0},{3,2},{4,0}} }
local t = s:insert_knot(1.5)
