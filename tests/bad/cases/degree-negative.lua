-- expect: 1 "bspline: degree is -1; it must be in [0, 32]"
-- degree -1
local s = bspline{ degree = -1, points = {{0,0},{1,2},{2,0},{3,2},{4,0}} }
