-- expect: 1 "reduce: tolerance is 0; it must be > 0"
-- a B-spline reduction with tolerance 0
local s = bspline{ degree = 3, points = { {0,0}, {1,2}, {2,0}, {3,2}, {4,0} } }
local r = s:reduce{ tolerance = 0 }
