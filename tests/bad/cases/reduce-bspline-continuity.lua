-- expect: 1 "reduce: unknown option 'continuity'; the options are by, tolerance or method"
-- a B-spline reduction keeps the curve's own continuity: no continuity option
local s = bspline{ degree = 3, points = { {0,0}, {1,2}, {2,0}, {3,2}, {4,0} } }
local r = s:reduce{ continuity = 1 }
