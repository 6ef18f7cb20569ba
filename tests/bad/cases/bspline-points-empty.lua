-- expect: 1 "bspline: 0 points given, at least 1 needed"
-- a B-spline without points
local s = bspline{ degree = 2, points = {} }
