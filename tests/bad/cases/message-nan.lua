-- expect: 1 "bspline: point P_4 coordinate 2 is NaN; coordinates must be finite"
-- 0/0 in a point: NaN, not "-nan"; the point by its mathematical index
local s = bspline{ degree = 2, knots = { 0, 0, 0, 0.5, 1, 1, 1 },
                   points = { {0, 0}, {1, 1}, {2, 0}, {3, 1}, {4, 0/0} } }
