-- expect: 1 "segment: [0.8, 0.2] is empty"
-- segment with a > b
local s = bspline{ degree = 2, points = {{0,0},{1,2},{2,0},{3,2},{4,0}} }
local t = s:segment(0.8, 0.2)
