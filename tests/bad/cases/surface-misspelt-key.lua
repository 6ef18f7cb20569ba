-- expect: 1 "bspline_surface: unknown field 'knot' (did you mean 'knots'?)"
-- a misspelt key of a surface constructor
local s = bspline_surface{ degree = 1, knot = {}, points = {
  { {0, 0, 0}, {1, 0, 0} }, { {0, 1, 0}, {1, 1, 1} } } }
