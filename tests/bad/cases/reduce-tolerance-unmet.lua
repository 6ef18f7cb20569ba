-- expect: 1 "reduce: reducing degree 3 to 2 needs an error of at least"
-- a B-spline reduction whose tolerance no quadratic can meet
local s = bspline{ degree = 3, points = { {0,0}, {1,2}, {2,0}, {3,2}, {4,0} } }
local r = s:reduce{ tolerance = 1e-6 }
