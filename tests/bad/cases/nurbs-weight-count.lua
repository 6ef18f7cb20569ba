-- expect: 1 "bspline: 6 weights given for 5 points"
-- six weights for five points
local s = bspline{ degree = 2, points = {{0,0},{1,2},{2,0},{3,2},{4,0}}, weights = {1, 1, 1, 1, 1, 1} }
