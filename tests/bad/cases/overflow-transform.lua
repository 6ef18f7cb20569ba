-- expect: 1 "transform: control point 0 of the transformed curve overflows (coordinate 1 is inf)"
-- an affine map with entries 1e300 applied to 1e300 coordinates
local s = bspline{ degree = 2, points = { {1e300, 0}, {1, 1}, {2, 0} } }
local t = s:transform({ {1e300, 0}, {0, 1e300} }, {0, 0})
