-- expect: 1 "refine: new knot 1 (0.20) is smaller than new knot 0 (0.70)"
-- refinement with decreasing values
local s = bspline{ degree = 2, points = {{0,0},{1,2},{2,0},{3,2},{4,0}} }
local t = s:refine{0.7, 0.2}
