-- expect: 1 "bspline: unknown field 'knot' (did you mean 'knots'?)"
-- a knot vector under a singular name
local s = bspline{ degree = 3, knot = {0, 0, 0, 0, 1, 1, 1, 1}, points = { {0, 0}, {1, 2}, {2, 0}, {3, 1} } }
