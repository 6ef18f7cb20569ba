-- expect: 1 "convex_hull: point 2 coordinate 1 is "
-- convex hull of a NaN point
local h = convex_hull{ {0, 0}, {0/0, 1}, {1, 0} }
