-- expect: 1 "bspline: knot u_4 (0.40) is smaller than knot u_3 (0.50)"
-- knots by their mathematical index, as the docs count them (u_0 first)
local s = bspline{ degree = 2, knots = { 0, 0, 0, 0.5, 0.4, 1, 1, 1 },
                   points = { {0, 0}, {1, 1}, {2, 0}, {3, 1}, {4, 0} } }
