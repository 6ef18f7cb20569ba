-- expect: 1 "bspline: degree must be an integer, got 2.5"
-- non-integer degree
local s = bspline{ degree = 2.5, points = {{0,0},{1,2},{2,0},{3,2},{4,0}} }
