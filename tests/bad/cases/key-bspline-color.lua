-- expect: 1 "bspline: 'color' is not a field: a curve has no style; give it to the drawing method"
-- a style given to a constructor
local s = bspline{ degree = 2, points = { {0, 0}, {1, 2}, {2, 0}, {3, 1} }, color = 'red' }
