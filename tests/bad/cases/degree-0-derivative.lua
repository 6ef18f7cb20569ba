-- expect: 1 "bspline: closed curves need a degree in 1..32, not 0"
-- degree 0 B-spline closed (needs degree >= 1)
local s = bspline{ degree = 0, kind = 'closed', points = {{0,0},{1,2},{2,0},{3,2},{4,0}} }
