-- expect: 1 "interpolate: natural cubic spline needs at least 2 points, got 1"
-- interpolation through one point
local s = interpolate{ points = {{0, 0}} }
