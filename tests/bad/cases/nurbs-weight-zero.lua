-- expect: 1 "bspline: weight w_1 is 0; weights must be finite and positive"
-- a zero NURBS weight
local s = bspline{ degree = 2, points = {{0,0},{1,2},{2,0},{3,2},{4,0}}, weights = {1, 0, 1, 1, 1} }
