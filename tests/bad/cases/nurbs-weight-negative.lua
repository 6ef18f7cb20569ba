-- expect: 1 "bspline: weight w_2 is -2; weights must be finite and positive"
-- a negative NURBS weight
local s = bspline{ degree = 2, points = {{0,0},{1,2},{2,0},{3,2},{4,0}}, weights = {1, 1, -2, 1, 1} }
