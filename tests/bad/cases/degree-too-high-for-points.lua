-- expect: 1 "bspline: degree 5 needs at least 6 points, 5 given"
-- degree 5 with 5 points
local s = bspline{ degree = 5, points = {{0,0},{1,2},{2,0},{3,2},{4,0}} }
