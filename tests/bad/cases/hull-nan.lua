-- expect: 1 "convex_hull: point P_1 coordinate 1 is NaN; coordinates must be finite"
-- convex hull of a NaN point
local h = convex_hull{ {0, 0}, {0/0, 1}, {1, 0} }
